#include "radiosity/LightIrradiance.h"

#include "lights/Light.h"
#include "sampling/StratifiedPoint.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"

namespace lancer {

Color LightIrradiance::at(const Scene& scene, const Vec3& p, const Vec3& ng, const Vec3& n,
                          int samples, std::uint64_t seed, std::uint64_t& rayCount) {
    Hit from;
    from.p = p;
    from.pError = gamma(16) * abs(p);
    from.ng = ng;
    Color E;
    for (std::size_t l = 0; l < scene.lights().size(); ++l) {
        const Light& light = *scene.lights()[l];
        const int count = light.isDelta() ? 1 : std::max(samples, light.shadowSamples());
        Color sum;
        for (int k = 0; k < count; ++k) {
            const Vec2 u =
                light.isDelta() ? Vec2(0.5f, 0.5f) : stratifiedPoint(k, count, hashValues(seed, l));
            const LightSample ls = light.sample(p, u);
            const float cosTheta = dot(n, ls.wi);
            if (!(cosTheta > 0) || ls.irradiance.isBlack() || !ls.irradiance.isFinite()) continue;
            sum += cosTheta * ls.irradiance * ShadowRays::transmittance(scene, from, ls, rayCount);
        }
        E += sum / static_cast<float>(count);
    }
    return E;
}

}  // namespace lancer
