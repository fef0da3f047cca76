// A scene's "animation" block: each frame loads the scene with the camera's keyframed keys and
// the named objects' transforms at that frame; the keys not keyframed stay as the scene gives
// them; a scene without the block is a still.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "TestSupport.h"
#include "io/SceneLoader.h"
#include "math/Bounds3.h"

namespace lancer {
namespace {

constexpr float kTolerance = 1e-5f;

// A ball of radius 1 moved from x = 0 at frame 1 to x = 4 at frame 5; the camera from z = 5 to
// z = 9 over the same frames, looking at the origin; a plane that stays.
const std::string kAnimated = R"({
  "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0], "vfov": 40 },
  "animation": {
    "frames": 7, "fps": 12, "interpolation": "INTERPOLATION",
    "camera": [ { "frame": 1, "position": [0, 0, 5] }, { "frame": 5, "position": [0, 0, 9] } ],
    "objects": {
      "ball": [ { "frame": 1, "transform": { "translate": [0, 0, 0] } },
                { "frame": 5, "transform": { "translate": [4, 0, 0] } } ]
    }
  },
  "objects": [
    { "type": "sphere", "name": "ball", "center": [0, 0, 0], "radius": 1 },
    { "type": "sphere", "name": "still", "center": [0, 0, -20], "radius": 1 }
  ]
})";

Scene loadFrame(const std::string& interpolation, int frame) {
    std::string text = kAnimated;
    text.replace(text.find("INTERPOLATION"), 13, interpolation);
    std::vector<std::string> warnings;
    Scene scene = SceneLoader::loadString(text, "animated.json", warnings, frame);
    EXPECT_TRUE(warnings.empty());
    return scene;
}

// Where the camera stands: the origin of its ray through the image's centre.
Vec3 cameraPosition(const Scene& scene) {
    return scene.camera().generateRay(32, 24, 64, 48, Vec2(0.5f, 0.5f))->origin;
}

// The x of the moving ball's centre: the middle of the scene's bounds once the still ball
// (whose x is 0) is accounted for.
float ballCentre(const Scene& scene) {
    return scene.bounds().max.x - 1;
}

TEST(AnimationLoaderTest, AStillSceneHasNoAnimation) {
    std::vector<std::string> warnings;
    const Scene scene =
        SceneLoader::loadString(R"({ "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] } })",
                                "still.json", warnings, 3);
    EXPECT_FALSE(scene.settings().animation);
}

TEST(AnimationLoaderTest, ReadsTheFramesAndTheirRate) {
    const Scene scene = loadFrame("linear", 1);
    ASSERT_TRUE(scene.settings().animation);
    EXPECT_EQ(scene.settings().animation->frames, 7);
    EXPECT_EQ(scene.settings().animation->framesPerSecond, 12);
}

TEST(AnimationLoaderTest, LinearMovesTheCameraAndTheObjectEvenly) {
    for (int frame = 1; frame <= 7; ++frame) {
        const Scene scene = loadFrame("linear", frame);
        const float along = static_cast<float>(std::min(frame, 5) - 1) / 4;
        EXPECT_VEC3_NEAR(cameraPosition(scene), Vec3(0, 0, 5 + 4 * along), kTolerance)
            << "frame " << frame;
        EXPECT_NEAR(ballCentre(scene), 4 * along, kTolerance) << "frame " << frame;
        // The keys that are not keyframed stay: the camera still looks at the origin.
        const Ray centre = *scene.camera().generateRay(32, 24, 64, 48, Vec2(0.5f, 0.5f));
        EXPECT_VEC3_NEAR(centre.direction, Vec3(0, 0, -1), kTolerance) << "frame " << frame;
    }
}

TEST(AnimationLoaderTest, SmoothEasesInAndOut) {
    // Two keyframes: smoothstep over frames 1 to 5, at rest at both.
    for (int frame = 1; frame <= 7; ++frame) {
        const float t = static_cast<float>(std::min(frame, 5) - 1) / 4;
        const float eased = t * t * (3 - 2 * t);
        const Scene scene = loadFrame("smooth", frame);
        EXPECT_VEC3_NEAR(cameraPosition(scene), Vec3(0, 0, 5 + 4 * eased), kTolerance)
            << "frame " << frame;
        EXPECT_NEAR(ballCentre(scene), 4 * eased, kTolerance) << "frame " << frame;
    }
}

}  // namespace
}  // namespace lancer
