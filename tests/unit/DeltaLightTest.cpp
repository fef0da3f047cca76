// Delta lights (points, spots, directions) are one sample exactly: the path tracer does not draw
// the point their sample would be given, so none of them may read it.

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "TestSupport.h"
#include "lights/DirectionalLight.h"
#include "lights/PointLight.h"
#include "lights/SpotLight.h"

namespace lancer {
namespace {

using test::Random;

TEST(DeltaLight, TheSampleDoesNotDependOnItsPoint) {
    std::vector<std::unique_ptr<Light>> lights;
    lights.push_back(std::make_unique<PointLight>(Vec3(0.5f, 2, -1), Color(3, 2, 1)));
    lights.push_back(std::make_unique<PointLight>(Vec3(-1, 1, 0), Color(1), false));
    lights.push_back(
        std::make_unique<SpotLight>(Vec3(0, 3, 0), Vec3(0.1f, -1, 0.2f), Color(8, 4, 2), 40, 10));
    lights.push_back(std::make_unique<DirectionalLight>(Vec3(0.3f, -1, 0.4f), Color(2)));
    Random random(5);
    for (const auto& light : lights) {
        ASSERT_TRUE(light->isDelta());
        for (int i = 0; i < 200; ++i) {
            const Vec3 p = random.pointInBox(2);
            const LightSample first = light->sample(p, Vec2(0, 0));
            const Vec2 u(static_cast<float>(random.uniform()),
                         static_cast<float>(random.uniform()));
            const LightSample other = light->sample(p, u);
            EXPECT_EQ(other.wi, first.wi);
            EXPECT_EQ(other.irradiance, first.irradiance);
            EXPECT_EQ(other.position, first.position);
            EXPECT_EQ(other.atInfinity, first.atInfinity);
            EXPECT_EQ(other.pdf, first.pdf);
        }
    }
}

}  // namespace
}  // namespace lancer
