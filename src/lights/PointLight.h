#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lights/Light.h"
#include "util/Parameters.h"

namespace lancer {

// A point light of radiant intensity `intensity`: E = I / d^2, or E = I at any distance when
// inverse-square falloff is turned off (POV-Ray's default behaviour).
class PointLight final : public Light {
public:
    PointLight(const Vec3& position, const Color& intensity, bool inverseSquareFalloff = true);
    // The scene file's "point" light: position, intensity, falloff.
    static std::vector<std::string> keys() { return {"position", "intensity", "falloff"}; }
    static std::unique_ptr<Light> create(const Parameters& parameters);
    // The "falloff" key: "inverse_square" (the default) or "none".
    static bool readInverseSquareFalloff(const Parameters& parameters);

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return true; }
    Color power(float sceneRadius) const override;

private:
    Vec3 position_;
    Color intensity_;
    bool inverseSquareFalloff_;
};

}  // namespace lancer
