#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lights/Light.h"
#include "util/Parameters.h"

namespace lancer {

// Light arriving from infinitely far away along `direction`, with irradiance `irradiance` on a
// surface facing it.
class DirectionalLight final : public Light {
public:
    // The scene file's "directional" light: direction, irradiance.
    static std::vector<std::string> keys() { return {"direction", "irradiance"}; }
    static std::unique_ptr<Light> create(const Parameters& parameters);
    DirectionalLight(const Vec3& direction, const Color& irradiance);

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return true; }
    Color power(float sceneRadius) const override;

private:
    Vec3 towardsLight_;
    Color irradiance_;
};

}  // namespace lancer
