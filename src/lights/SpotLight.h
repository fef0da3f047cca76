#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lights/Light.h"
#include "util/Parameters.h"

namespace lancer {

// A point light that shines into a cone: radiant intensity `intensity` along `direction`, out to
// `coneAngle - coneFalloff` degrees off the axis, from there fading smoothly (a smoothstep of the
// cosine, as in pbrt-v4) to nothing at `coneAngle` degrees and beyond. E = I(angle) / d^2, or E =
// I(angle) without inverse-square falloff, as for point lights.
class SpotLight final : public Light {
public:
    // The scene file's "spot" light.
    static std::vector<std::string> keys() {
        return {"position",   "direction",    "look_at", "intensity",
                "cone_angle", "cone_falloff", "falloff"};
    }
    static std::unique_ptr<Light> create(const Parameters& parameters);
    SpotLight(const Vec3& position, const Vec3& direction, const Color& intensity,
              float coneAngleDegrees, float coneFalloffDegrees, bool inverseSquareFalloff = true);

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return true; }
    Color power(float sceneRadius) const override;

    // The fraction of the intensity sent along the unit direction w leaving the light.
    float coneFactor(const Vec3& w) const;

private:
    Vec3 position_;
    Vec3 direction_;  // unit
    Color intensity_;
    float cosConeAngle_;     // no light beyond this cosine...
    float cosFalloffStart_;  // ...and full intensity within this one
    bool inverseSquareFalloff_;
};

}  // namespace lancer
