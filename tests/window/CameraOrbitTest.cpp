// The window's camera moves: orbiting around look_at and zooming.

#include "scene/CameraOrbit.h"

#include <gtest/gtest.h>

#include "math/Float.h"
#include "scene/OrthographicCamera.h"
#include "scene/PerspectiveCamera.h"

namespace lancer {
namespace {

constexpr float kTolerance = 1e-4f;

void expectNear(const Vec3& a, const Vec3& b) {
    EXPECT_NEAR(a.x, b.x, kTolerance);
    EXPECT_NEAR(a.y, b.y, kTolerance);
    EXPECT_NEAR(a.z, b.z, kTolerance);
}

const PerspectiveCamera kCamera(CameraFrame(Vec3(0, 1, 5), Vec3(0, 1, 0), Vec3(0, 1, 0)), 40, 0.1f,
                                4);

// The orbit's camera is of the original's type: a perspective camera here.
const PerspectiveCamera& perspective(const std::unique_ptr<Camera>& camera) {
    return static_cast<const PerspectiveCamera&>(*camera);
}

TEST(CameraOrbit, UnmovedItIsTheOriginalCamera) {
    const std::unique_ptr<Camera> moved = CameraOrbit(kCamera).camera();
    const PerspectiveCamera& camera = perspective(moved);
    expectNear(camera.position(), kCamera.position());
    expectNear(camera.lookAt(), kCamera.lookAt());
    EXPECT_EQ(camera.vfovDegrees(), kCamera.vfovDegrees());
    EXPECT_EQ(camera.aperture(), kCamera.aperture());
    EXPECT_NEAR(camera.focusDistance(), kCamera.focusDistance(), kTolerance);
}

TEST(CameraOrbit, AQuarterTurnAroundUpKeepsTheDistanceAndTheTarget) {
    CameraOrbit orbit(kCamera);
    orbit.rotate(kPi / 2, 0);
    const std::unique_ptr<Camera> moved = orbit.camera();
    const PerspectiveCamera& camera = perspective(moved);
    // From +z, a counter-clockwise quarter turn seen from above lands on +x.
    expectNear(camera.position(), Vec3(5, 1, 0));
    expectNear(camera.lookAt(), kCamera.lookAt());
    EXPECT_NEAR(camera.focusDistance(), 4, kTolerance);
}

TEST(CameraOrbit, TiltingStopsShortOfStraightDown) {
    CameraOrbit orbit(kCamera);
    orbit.rotate(0, 10);  // far past the pole
    const Vec3 offset = orbit.camera()->position() - kCamera.lookAt();
    EXPECT_NEAR(length(offset), 5, kTolerance);
    EXPECT_NEAR(std::asin(offset.y / 5), radians(89), 1e-3f);
    // The camera still has a well-defined frame: the ray through the centre points at look_at.
    const Ray centre = *orbit.camera()->generateRay(50, 50, 100, 100, Vec2(0.5f, 0.5f));
    expectNear(normalize(centre.direction),
               normalize(kCamera.lookAt() - orbit.camera()->position()));
}

TEST(CameraOrbit, ZoomScalesTheDistanceAndTheFocusAndIsBounded) {
    CameraOrbit orbit(kCamera);
    orbit.zoom(0.5f);
    expectNear(orbit.camera()->position(), Vec3(0, 1, 2.5f));
    EXPECT_NEAR(perspective(orbit.camera()).focusDistance(), 2, kTolerance);
    for (int i = 0; i < 100; ++i)
        orbit.zoom(0.5f);
    EXPECT_NEAR(length(orbit.camera()->position() - kCamera.lookAt()), 0.05f, kTolerance)
        << "never closer than 1/100 of the distance: the camera never reaches look_at";
}

// An orthographic camera stays orthographic (parallel rays along the new view direction), and
// the wheel scales its view's height as it scales the distance.
TEST(CameraOrbit, MovesAnOrthographicCameraAndZoomScalesItsHeight) {
    const OrthographicCamera original(CameraFrame(Vec3(0, 1, 5), Vec3(0, 1, 0), Vec3(0, 1, 0)), 4);
    CameraOrbit orbit(original);
    orbit.rotate(kPi / 2, 0);
    orbit.zoom(0.5f);
    const std::unique_ptr<Camera> moved = orbit.camera();
    expectNear(moved->position(), Vec3(2.5f, 1, 0));
    const Ray corner = *moved->generateRay(0, 0, 100, 50, Vec2(0.5f, 0.5f));
    const Ray centre = *moved->generateRay(50, 25, 100, 50, Vec2(0.5f, 0.5f));
    expectNear(corner.direction, Vec3(-1, 0, 0));
    expectNear(centre.direction, Vec3(-1, 0, 0));
    expectNear(centre.origin, Vec3(2.5f, 1, 0));
    // Height 4 halved: the top-left corner is 1 up and 2 to the left (+z, seen from +x).
    expectNear(corner.origin, Vec3(2.5f, 2, 2));
}

}  // namespace
}  // namespace lancer
