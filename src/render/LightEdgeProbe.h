#pragma once

#include <cstdint>
#include <vector>

#include "render/PixelWindow.h"

namespace lancer {

class Scene;

// Finds the pixels across whose area the light the camera sees directly jumps: the edge of an
// area light, of the sun in an environment map, of a bright background behind an object. There
// a pixel's few samples land on either side in proportions far from the pixel's, and at low
// sample counts these pixels hold most of a render's error (the rim of the Cornell box's light:
// 0.2% of the pixels, about half the squared error at 4 spp); the renderer gives them more
// samples (RenderSettings::lightEdgeFactor).
//
// The test looks at the pixel's four corners, where one camera ray each (through the lens's
// centre) meets a surface or leaves the scene: the pixel is on an edge when the luminance those
// rays see emitted differs by more than display white between two corners. It depends on the
// pixel's place alone, never on its samples, so the pixel's estimate stays unbiased, and the
// image stays the same whatever the tiles and threads. A light smaller than a pixel can fall
// between the corners; its pixels keep their samples.
class LightEdgeProbe {
public:
    // The scene's exposure scales the step that makes an edge with display white, the radiance
    // the outputs show as white: 2^-exposure. Fainter steps are left to the pixels' samples.
    explicit LightEdgeProbe(const Scene& scene);

    // Whether edges are looked for: the scene's lightEdgeFactor and spp are above 1 (a pixel of
    // 1 spp is the classic ray tracer's one ray through its centre, every pixel alike), and it
    // has an emitting surface, an environment, or a background brighter than display white
    // (without them no step can be brighter). Otherwise edges() finds none and traces nothing.
    bool active() const { return active_; }

    // For each pixel of `window`, row by row, whether it is on an edge. The corners shared by
    // neighbouring pixels are traced once; rayCount counts them.
    std::vector<bool> edges(const PixelWindow& window, std::uint64_t& rayCount) const;

private:
    // The luminance emitted towards the camera at image point (px, py): by the surface its ray
    // meets, or by the environment or background where it leaves the scene; 0 where the camera
    // sees nothing.
    float seenLuminance(float px, float py, std::uint64_t& rayCount) const;

    const Scene& scene_;
    float white_;  // the luminance step that makes an edge
    bool active_;
};

}  // namespace lancer
