#pragma once

#include <memory>
#include <string>
#include <vector>

#include "image/Image.h"
#include "lights/Light.h"
#include "math/Distribution2D.h"
#include "util/Parameters.h"

namespace lancer {

// Light from infinitely far away in every direction, from a latitude-longitude map: a ray
// leaving the scene with unit direction d (the map's rotation about +y undone) sees the map at
// u = 0.5 + atan2(d.x, -d.z) / (2 pi) across and v = acos(d.y) / pi down, bilinearly (the
// scene format's "environment"). Directions are sampled in proportion to the map's luminance
// times sin(theta), the Jacobian of the mapping: a texel's cell through a Distribution2D (by the
// cell's average luminance), then a point in the cell in proportion to the bilinear luminance.
// The texels are kept with a border (a column wrapped around on each side, the pole rows
// repeated), so that a lookup reads its four texels without wrapping or clamping, and each with
// its luminance, which a sample reads nine of around its cell before it looks the point up in
// the same cache lines. Beside BSDF sampling (sampleBesideBsdf), the cells are picked by how far
// their average luminance exceeds the whole map's instead (Karlik et al. 2019): the dim sky,
// which BSDF sampling finds well, is left to it, and the light's samples go to the sun.
class EnvironmentLight final : public Light {
public:
    // The scene file's "environment": its keys besides "file" (read by the loader, which gives
    // the image) and "samples" (the Whitted shadow samples, as for area lights).
    static std::vector<std::string> keys() { return {"file", "intensity", "rotate", "samples"}; }
    static std::unique_ptr<EnvironmentLight> create(const Parameters& parameters, Image map);
    // `map` holds linear radiance; it is scaled by `intensity` and turned by `rotateDegrees`
    // about +y (counter-clockwise seen from above).
    EnvironmentLight(Image map, float intensity, float rotateDegrees);

    // The radiance arriving from direction d (towards the environment; any length).
    Color radiance(const Vec3& d) const;

    // What a ray leaving the scene along d finds: the radiance, and the solid-angle density with
    // which sample() picks d (pdf()), from one lookup.
    struct Arrival {
        Color radiance;
        float pdf;
    };
    Arrival arrival(const Vec3& d) const;
    // The same with the density of sampleBesideBsdf().
    Arrival arrivalBesideBsdf(const Vec3& d) const;

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return false; }
    float pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const override;
    LightSample sampleBesideBsdf(const Vec3& p, const Vec2& u) const override;
    float pdfBesideBsdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const override;
    // The flux through a disc as wide as the scene from every direction: pi R^2 times the
    // integral of the radiance over the sphere.
    Color power(float sceneRadius) const override;

    // The map's point (u, v) in [0, 1)^2 of a unit direction in the map's own frame, and back.
    static Vec2 mapPoint(const Vec3& d);
    static Vec3 mapDirection(const Vec2& uv);

private:
    // A texel's radiance and luminance in one 16-byte block.
    struct alignas(16) Texel {
        Color radiance;
        float luminance;
    };
    // The map scaled by `intensity`, with its border.
    static std::vector<Texel> borderedTexels(const Image& map, float intensity);
    // The texel (x, y) for x in [-1, w] (wrapping around) and y in [-1, h] (the pole rows
    // repeated), and its luminance.
    const Color& texel(int x, int y) const { return texels_[bordered(x, y)].radiance; }
    float luminance(int x, int y) const { return texels_[bordered(x, y)].luminance; }
    std::size_t bordered(int x, int y) const {
        return static_cast<std::size_t>(y + 1) * static_cast<std::size_t>(width_ + 2) +
               static_cast<std::size_t>(x + 1);
    }
    // How cells are picked, then a point in the cell in proportion to the bilinear luminance:
    // the density over the map's (u, v) there is rowDensity[y] * cellShare[cell] * luminance
    // (cellShare empty: 1 for every cell).
    struct Strategy {
        Distribution2D cells;
        std::vector<float> rowDensity;
        std::vector<float> cellShare;
    };
    // Cell (x, y)'s place in the per-cell arrays, row by row.
    std::size_t cell(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }
    // Each cell's luminance averaged over it as the bilinear lookup spreads it.
    std::vector<float> cellMeans() const;
    // sample()'s and sampleBesideBsdf()'s, from the cells' means computed once.
    struct Strategies {
        Strategy alone;       // by the cells' mean luminance times sin(theta)
        Strategy besideBsdf;  // by its excess over the map's mean
    };
    Strategies strategies() const;
    // By the cells' mean luminance times sin(theta); by its excess over the map's mean (or, for
    // a map without any, as the former).
    Strategy wholeMap(const std::vector<float>& means) const;
    Strategy aboveAverage(const std::vector<float>& means) const;
    // The distribution of `weights` (per cell, row by row) with its row densities.
    Strategy strategy(const std::vector<float>& weights, std::vector<float> cellShare) const;
    LightSample sampleBy(const Strategy& strategy, const Vec2& u) const;
    Arrival arrivalBy(const Strategy& strategy, const Vec3& d) const;
    // The bilinear lookup at (u, v) in [0, 1)^2.
    Color lookUp(const Vec2& uv) const;
    // A point of texel (x, y)'s cell in proportion to the bilinear luminance there, from u.
    Vec2 sampleInCell(int x, int y, Vec2 u) const;
    // The density over the map's (u, v) with which `strategy` picks a point where the lookup
    // gives `radiance`.
    float mapDensity(const Strategy& strategy, const Vec2& uv, const Color& radiance) const;
    // The solid-angle density of the direction of map point uv, from its density over (u, v).
    static float solidAngleDensity(float mapDensity, float sinTheta);
    Vec3 toMap(const Vec3& world) const;
    Vec3 toWorld(const Vec3& map) const;

    int width_, height_;
    float cosRotate_, sinRotate_;
    std::vector<Texel> texels_;  // the map scaled by the intensity, with its border
    Strategies strategies_;
    Color radianceIntegral_;  // the integral of the radiance over the sphere of directions
};

}  // namespace lancer
