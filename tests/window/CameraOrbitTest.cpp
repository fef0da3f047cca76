// The window's camera moves: orbiting around look_at and zooming.

#include "scene/CameraOrbit.h"

#include <gtest/gtest.h>

#include "math/Float.h"

namespace lancer {
namespace {

constexpr float kTolerance = 1e-4f;

void expectNear(const Vec3& a, const Vec3& b) {
    EXPECT_NEAR(a.x, b.x, kTolerance);
    EXPECT_NEAR(a.y, b.y, kTolerance);
    EXPECT_NEAR(a.z, b.z, kTolerance);
}

const Camera kCamera(Vec3(0, 1, 5), Vec3(0, 1, 0), Vec3(0, 1, 0), 40, 0.1f, 4);

TEST(CameraOrbit, UnmovedItIsTheOriginalCamera) {
    const Camera camera = CameraOrbit(kCamera).camera();
    expectNear(camera.position(), kCamera.position());
    expectNear(camera.lookAt(), kCamera.lookAt());
    EXPECT_EQ(camera.vfovDegrees(), kCamera.vfovDegrees());
    EXPECT_EQ(camera.aperture(), kCamera.aperture());
    EXPECT_NEAR(camera.focusDistance(), kCamera.focusDistance(), kTolerance);
}

TEST(CameraOrbit, AQuarterTurnAroundUpKeepsTheDistanceAndTheTarget) {
    CameraOrbit orbit(kCamera);
    orbit.rotate(kPi / 2, 0);
    const Camera camera = orbit.camera();
    // From +z, a counter-clockwise quarter turn seen from above lands on +x.
    expectNear(camera.position(), Vec3(5, 1, 0));
    expectNear(camera.lookAt(), kCamera.lookAt());
    EXPECT_NEAR(camera.focusDistance(), 4, kTolerance);
}

TEST(CameraOrbit, TiltingStopsShortOfStraightDown) {
    CameraOrbit orbit(kCamera);
    orbit.rotate(0, 10);  // far past the pole
    const Vec3 offset = orbit.camera().position() - kCamera.lookAt();
    EXPECT_NEAR(length(offset), 5, kTolerance);
    EXPECT_NEAR(std::asin(offset.y / 5), radians(89), 1e-3f);
    // The camera still has a well-defined frame: the ray through the centre points at look_at.
    const Ray centre = orbit.camera().generateRay(50, 50, 100, 100, Vec2(0.5f, 0.5f));
    expectNear(normalize(centre.direction),
               normalize(kCamera.lookAt() - orbit.camera().position()));
}

TEST(CameraOrbit, ZoomScalesTheDistanceAndTheFocusAndIsBounded) {
    CameraOrbit orbit(kCamera);
    orbit.zoom(0.5f);
    expectNear(orbit.camera().position(), Vec3(0, 1, 2.5f));
    EXPECT_NEAR(orbit.camera().focusDistance(), 2, kTolerance);
    for (int i = 0; i < 100; ++i)
        orbit.zoom(0.5f);
    EXPECT_NEAR(length(orbit.camera().position() - kCamera.lookAt()), 0.05f, kTolerance)
        << "never closer than 1/100 of the distance: the camera never reaches look_at";
}

}  // namespace
}  // namespace lancer
