// Loading area and spot lights: each light is what its keys say, and an area light's visible
// surface is in the scene, linked to it, emitting its radiance and reflecting nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "IntersectInto.h"
#include "TestSupport.h"
#include "geometry/Shape.h"
#include "io/SceneLoader.h"
#include "lights/AreaLight.h"
#include "lights/Light.h"
#include "lights/SpotLight.h"
#include "materials/BlinnPhongMaterial.h"
#include "materials/Material.h"

namespace lancer {
namespace {

Scene loadLights(const std::string& lights) {
    std::vector<std::string> warnings;
    Scene scene = SceneLoader::loadString(
        R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }, "lights": [)" + lights +
            "] }",
        "test.json", warnings);
    EXPECT_TRUE(warnings.empty());
    return scene;
}

TEST(LightLoaderTest, AQuadLightIsAVisibleSurfaceLinkedToItsLight) {
    const Scene scene = loadLights(R"({ "type": "quad", "corner": [-1, -1, 0], "edge1": [2, 0, 0],
        "edge2": [0, 2, 0], "radiance": [1, 2, 3] })");
    ASSERT_EQ(scene.lights().size(), 1u);
    const auto* light = dynamic_cast<const AreaLight*>(scene.lights()[0].get());
    ASSERT_NE(light, nullptr);
    EXPECT_EQ(light->radiance(), Color(1, 2, 3));
    EXPECT_EQ(light->shadowSamples(), 16) << "the default";
    EXPECT_EQ(light->shape().area(0), 4);
    EXPECT_EQ(light->shape().sample(0, Vec2(0.5f, 0.5f))->n, Vec3(0, 0, 1));

    Hit hit;
    ASSERT_TRUE(test::intersectInto(scene, {Vec3(0.5f, 0.5f, 5), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_EQ(hit.shape->areaLight(), light);
    EXPECT_EQ(hit.material->emission(), Color(1, 2, 3));
    EXPECT_TRUE(hit.material->diffuseReflectance(hit).isBlack());
    EXPECT_TRUE(hit.material->ambientReflectance(hit).isBlack());
    EXPECT_TRUE(
        dynamic_cast<const BlinnPhongMaterial&>(*hit.material).parameters().specular.isBlack());
    EXPECT_FALSE(hit.shape->emitsOnBothSides());
}

TEST(LightLoaderTest, ASphereLightIsAVisibleSphereLinkedToItsLight) {
    const Scene scene = loadLights(
        R"({ "type": "sphere", "center": [0, 0, -1], "radius": 0.5, "radiance": 7, "samples": 9 })");
    ASSERT_EQ(scene.lights().size(), 1u);
    const auto* light = dynamic_cast<const AreaLight*>(scene.lights()[0].get());
    ASSERT_NE(light, nullptr);
    EXPECT_EQ(light->shadowSamples(), 9);
    EXPECT_FLOAT_EQ(light->shape().area(0), kPi) << "radius 0.5";
    Hit hit;
    ASSERT_TRUE(test::intersectInto(scene, {Vec3(0, 0, 5), Vec3(0, 0, -1)}, kInfinity, hit));
    EXPECT_EQ(hit.t, 5.5f);
    EXPECT_EQ(hit.shape->areaLight(), light);
    EXPECT_EQ(hit.material->emission(), Color(7));
    EXPECT_TRUE(hit.material->diffuseReflectance(hit).isBlack());
}

TEST(LightLoaderTest, ASpotLightAimsAlongItsDirectionOrAtItsLookAtPoint) {
    const Scene scene = loadLights(R"(
        { "type": "spot", "position": [0, 4, 0], "direction": [0, -2, 0], "intensity": 16,
          "cone_angle": 10, "cone_falloff": 2 },
        { "type": "spot", "position": [0, 4, 0], "look_at": [0, 1, 0], "intensity": 16,
          "cone_angle": 10, "cone_falloff": 2, "falloff": "none" })");
    ASSERT_EQ(scene.lights().size(), 2u);
    for (const auto& light : scene.lights()) {
        ASSERT_NE(dynamic_cast<const SpotLight*>(light.get()), nullptr);
        EXPECT_EQ(light->shadowSamples(), 1);
    }
    EXPECT_EQ(scene.lights()[0]->sample(Vec3(0, 0, 0), Vec2(0.5f, 0.5f)).irradiance, Color(1));
    EXPECT_EQ(scene.lights()[1]->sample(Vec3(0, 0, 0), Vec2(0.5f, 0.5f)).irradiance, Color(16));
    // 9 degrees off the axis is in the fade, 11 degrees is outside.
    const auto off = [](float degrees) { return Vec3(4 * std::tan(radians(degrees)), 0, 0); };
    const float faded = scene.lights()[0]->sample(off(9), Vec2(0.5f, 0.5f)).irradiance.r;
    EXPECT_GT(faded, 0);
    EXPECT_LT(faded, 1);
    EXPECT_TRUE(scene.lights()[0]->sample(off(11), Vec2(0.5f, 0.5f)).irradiance.isBlack());
}

TEST(LightLoaderTest, ASpotLightDefaultsToAThirtyDegreeConeFadingOverFive) {
    const Scene scene = loadLights(
        R"({ "type": "spot", "position": [0, 4, 0], "direction": [0, -1, 0], "intensity": 16 })");
    const Light& light = *scene.lights()[0];
    const auto at = [&](float degrees) {
        return light.sample(Vec3(4 * std::tan(radians(degrees)), 0, 0), Vec2(0.5f, 0.5f))
            .irradiance.r;
    };
    const float cos249 = std::cos(radians(24.9f));
    EXPECT_NEAR(at(24.9f), cos249 * cos249, 1e-5) << "full intensity: 16 / d^2, d = 4 / cos";
    EXPECT_GT(at(27), 0);
    EXPECT_LT(at(27), std::cos(radians(27.0f)) * std::cos(radians(27.0f)));
    EXPECT_EQ(at(30.1f), 0);
}

}  // namespace
}  // namespace lancer
