// The cameras beside the perspective one: each ray against its documented formula, computed
// independently in double precision, and the footprints they give texture filtering.

#include <gtest/gtest.h>

#include <cmath>

#include "TestSupport.h"
#include "scene/FisheyeCamera.h"
#include "scene/LatLongCamera.h"
#include "scene/OrthographicCamera.h"

namespace lancer {
namespace {

// Float evaluation of a few sines, cosines and a normalization: a few units in the last place.
constexpr float kTolerance = 4e-6f;
constexpr double kPi = 3.14159265358979323846;
const Vec2 kLensCentre(0.5f, 0.5f);

// An oblique frame: looking down and sideways, with an "up" not orthogonal to the view.
struct FrameSpec {
    Vec3d position{1, 2, 6}, lookAt{0, 0.5, -1}, up{0.1, 1, 0};

    Vec3d w() const { return normalize(position - lookAt); }
    Vec3d u() const { return normalize(cross(up, w())); }
    Vec3d v() const { return cross(w(), u()); }
    Vec3d toWorld(const Vec3d& d) const { return d.x * u() + d.y * v() + d.z * w(); }
    Vec3d toLocal(const Vec3d& d) const { return Vec3d(dot(d, u()), dot(d, v()), dot(d, w())); }
    CameraFrame frame() const { return CameraFrame(Vec3(position), Vec3(lookAt), Vec3(up)); }
};
const FrameSpec kFrame;
constexpr int kWidth = 320, kHeight = 200;

// The pixel centres visited: a coarse grid over the image, with the edges.
template <typename Check>
void forSomePixels(Check check) {
    for (int j = 0; j < kHeight; j += 13)
        for (int i = 0; i < kWidth; i += 11)
            check(i + 0.5, j + 0.5);
}

// --- orthographic ---

// origin = position + (2 px / width - 1) (height / 2) (width / height) u
//                   + (1 - 2 py / height) (height / 2) v, direction = -w.
TEST(OrthographicCamera, RaysFollowTheFormula) {
    constexpr double kViewHeight = 3;
    const OrthographicCamera camera(kFrame.frame(), static_cast<float>(kViewHeight));
    forSomePixels([&](double px, double py) {
        const Ray ray = *camera.generateRay(static_cast<float>(px), static_cast<float>(py), kWidth,
                                            kHeight, kLensCentre);
        const Vec3d origin =
            kFrame.position +
            (2 * px / kWidth - 1) * (kViewHeight / 2) * kWidth / kHeight * kFrame.u() +
            (1 - 2 * py / kHeight) * (kViewHeight / 2) * kFrame.v();
        // The origin is a sum of terms of size about 6: a few ulps of that.
        EXPECT_VEC3_NEAR(ray.origin, Vec3(origin), 4e-6f * 8) << px << ", " << py;
        EXPECT_VEC3_NEAR(ray.direction, Vec3(-kFrame.w()), kTolerance);
    });
}

TEST(OrthographicCamera, TheViewIsHeightHighAndAsWideAsTheAspectRatio) {
    const OrthographicCamera camera(kFrame.frame(), 2);
    const Ray topLeft = *camera.generateRay(0, 0, 300, 100, kLensCentre);
    const Ray bottomRight = *camera.generateRay(300, 100, 300, 100, kLensCentre);
    const Vec3d across = Vec3d(bottomRight.origin) - Vec3d(topLeft.origin);
    EXPECT_NEAR(dot(across, kFrame.u()), 6, 1e-5);
    EXPECT_NEAR(dot(across, kFrame.v()), -2, 1e-5);
    EXPECT_NEAR(dot(across, kFrame.w()), 0, 1e-5);
}

TEST(OrthographicCamera, ThePixelFootprintIsAPixelWideAtAnyDistance) {
    const RayCone cone = OrthographicCamera(kFrame.frame(), 3).pixelCone(kWidth, kHeight);
    EXPECT_FLOAT_EQ(cone.width, 3.0f / kHeight);
    EXPECT_EQ(cone.spread, 0);
    EXPECT_FLOAT_EQ(cone.widthAt(1000), 3.0f / kHeight);
}

// --- fisheye ---

// x = (px - width / 2) / R, y = (height / 2 - py) / R with R = min(width, height) / 2;
// r = sqrt(x^2 + y^2) <= 1, theta = r fov / 2: direction sin(theta) (x, y) / r u, v
// and -cos(theta) w.
Vec3d fisheyeDirection(double px, double py, double fovDegrees) {
    const double radius = std::min(kWidth, kHeight) / 2.0;
    const double x = (px - kWidth / 2.0) / radius, y = (kHeight / 2.0 - py) / radius;
    const double r = std::hypot(x, y);
    const double theta = r * fovDegrees * kPi / 180 / 2;
    if (r == 0) return -kFrame.w();
    return kFrame.toWorld(
        Vec3d(std::sin(theta) * x / r, std::sin(theta) * y / r, -std::cos(theta)));
}

TEST(FisheyeCamera, RaysInsideTheCircleFollowTheFormulaAndNoneOutside) {
    for (const double fov : {90.0, 180.0, 250.0, 360.0}) {
        const FisheyeCamera camera(kFrame.frame(), static_cast<float>(fov));
        int inside = 0, outside = 0;
        forSomePixels([&](double px, double py) {
            const std::optional<Ray> ray = camera.generateRay(
                static_cast<float>(px), static_cast<float>(py), kWidth, kHeight, kLensCentre);
            const double r = std::hypot(px - kWidth / 2.0, py - kHeight / 2.0) / (kHeight / 2.0);
            if (r > 1) {
                EXPECT_FALSE(ray) << px << ", " << py;
                ++outside;
                return;
            }
            ASSERT_TRUE(ray) << px << ", " << py;
            ++inside;
            EXPECT_EQ(ray->origin, Vec3(kFrame.position));
            EXPECT_VEC3_NEAR(ray->direction, Vec3(fisheyeDirection(px, py, fov)), kTolerance)
                << "fov " << fov << ", " << px << ", " << py;
        });
        EXPECT_GT(inside, 100);
        EXPECT_GT(outside, 100);
    }
}

TEST(FisheyeCamera, TheCircleSeesHalfTheFieldOfViewAtItsRim) {
    const float cx = kWidth / 2.0f, cy = kHeight / 2.0f, radius = kHeight / 2.0f;
    const FisheyeCamera hemisphere(kFrame.frame(), 180);
    EXPECT_VEC3_NEAR(hemisphere.generateRay(cx, cy, kWidth, kHeight, kLensCentre)->direction,
                     Vec3(-kFrame.w()), kTolerance);
    // 180 degrees: the rim looks sideways (along v at the top, along u at the right).
    EXPECT_VEC3_NEAR(hemisphere.generateRay(cx, 0, kWidth, kHeight, kLensCentre)->direction,
                     Vec3(kFrame.v()), kTolerance);
    EXPECT_VEC3_NEAR(
        hemisphere.generateRay(cx + radius, cy, kWidth, kHeight, kLensCentre)->direction,
        Vec3(kFrame.u()), kTolerance);
    // 360 degrees: the rim looks straight back.
    const FisheyeCamera sphere(kFrame.frame(), 360);
    EXPECT_VEC3_NEAR(sphere.generateRay(cx - radius, cy, kWidth, kHeight, kLensCentre)->direction,
                     Vec3(kFrame.w()), kTolerance);
    // Just beyond the rim: nothing.
    EXPECT_FALSE(hemisphere.generateRay(cx, cy + radius * 1.001f, kWidth, kHeight, kLensCentre));
}

TEST(FisheyeCamera, ThePixelSpreadIsTheAngleBetweenNeighboursAlongARadius) {
    const FisheyeCamera camera(kFrame.frame(), 180);
    const RayCone cone = camera.pixelCone(kWidth, kHeight);
    EXPECT_EQ(cone.width, 0);
    const float cx = kWidth / 2.0f, cy = kHeight / 2.0f;
    for (const float x : {cx + 0.5f, cx + 50.5f, cx + 98.5f}) {
        const Vec3 a = camera.generateRay(x, cy, kWidth, kHeight, kLensCentre)->direction;
        const Vec3 b = camera.generateRay(x + 1, cy, kWidth, kHeight, kLensCentre)->direction;
        EXPECT_NEAR(std::acos(dot(a, b)), cone.spread, 1e-3 * cone.spread) << x;
    }
}

// --- lat-long ---

// The environment map's lookup, in the camera's frame: u = 0.5 + atan2(d.x, -d.z) / (2 pi),
// v = acos(d.y) / pi. The lat-long camera is its inverse.
TEST(LatLongCamera, EachPixelLooksWhereTheEnvironmentMappingPutsIt) {
    const LatLongCamera camera(kFrame.frame());
    forSomePixels([&](double px, double py) {
        const Ray ray = *camera.generateRay(static_cast<float>(px), static_cast<float>(py), kWidth,
                                            kHeight, kLensCentre);
        EXPECT_EQ(ray.origin, Vec3(kFrame.position));
        EXPECT_NEAR(length(ray.direction), 1, kTolerance);
        const Vec3d d = kFrame.toLocal(Vec3d(ray.direction));
        const double u = 0.5 + std::atan2(d.x, -d.z) / (2 * kPi);
        const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi;
        // A direction good to a few ulps is within a few 1e-6 radians.
        EXPECT_NEAR(u * kWidth, px, 1e-5 * kWidth / (2 * kPi) * 4 / std::sin(v * kPi))
            << px << ", " << py;
        EXPECT_NEAR(v * kHeight, py, 4e-3) << px << ", " << py;
    });
}

TEST(LatLongCamera, TheCentreLooksAheadTheTopUpAndThreeQuartersAcrossRight) {
    const LatLongCamera camera(kFrame.frame());
    const auto direction = [&](float px, float py) {
        return camera.generateRay(px, py, kWidth, kHeight, kLensCentre)->direction;
    };
    EXPECT_VEC3_NEAR(direction(kWidth / 2.0f, kHeight / 2.0f), Vec3(-kFrame.w()), kTolerance);
    EXPECT_VEC3_NEAR(direction(kWidth / 3.0f, 0), Vec3(kFrame.v()), kTolerance);
    EXPECT_VEC3_NEAR(direction(kWidth / 3.0f, kHeight), Vec3(-kFrame.v()), kTolerance);
    EXPECT_VEC3_NEAR(direction(kWidth * 0.75f, kHeight / 2.0f), Vec3(kFrame.u()), kTolerance);
    EXPECT_VEC3_NEAR(direction(kWidth * 0.25f, kHeight / 2.0f), Vec3(-kFrame.u()), kTolerance);
    EXPECT_VEC3_NEAR(direction(0, kHeight / 2.0f), Vec3(kFrame.w()), kTolerance);
}

TEST(LatLongCamera, ThePixelSpreadIsTheAngleBetweenRows) {
    const RayCone cone = LatLongCamera(kFrame.frame()).pixelCone(kWidth, kHeight);
    EXPECT_EQ(cone.width, 0);
    EXPECT_FLOAT_EQ(cone.spread, static_cast<float>(kPi / kHeight));
}

}  // namespace
}  // namespace lancer
