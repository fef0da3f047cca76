#pragma once

#include <cstdint>

#include "math/Ray.h"
#include "render/AovSample.h"

namespace lancer {

class Scene;

// Follows a camera ray to its first hit (the normal and depth outputs) and on through mirrors
// and glass to the first surface with a diffuse colour (the albedo output), whatever the
// integrator: the auxiliary outputs a denoiser takes. Deterministic: no sampler is drawn from, so
// the image's samples are the same with or without it.
class FirstHitProbe {
public:
    explicit FirstHitProbe(const Scene& scene);

    // rayCount is incremented for every ray traced.
    AovSample probe(const Ray& cameraRay, std::uint64_t& rayCount) const;

private:
    const Scene& scene_;
    int maxDepth_;  // specular bounces followed at most, as the integrators' max_depth
};

}  // namespace lancer
