// The camera of the contract: the pinhole ray formula, and the thin lens around it.

#include <gtest/gtest.h>

#include <cmath>

#include "TestSupport.h"
#include "scene/PerspectiveCamera.h"

namespace lancer {
namespace {

using test::Random;

// Float evaluation of a normalized direction: a few units in the last place.
constexpr float kTolerance = 2e-6f;
constexpr double kPi = 3.14159265358979323846;

// The contract's camera, computed independently in double precision.
struct CameraSpec {
    Vec3d position, lookAt, up;
    double vfovDegrees;
    int width, height;

    Vec3d w() const { return normalize(position - lookAt); }
    Vec3d u() const { return normalize(cross(up, w())); }
    Vec3d v() const { return cross(w(), u()); }
    double tanH() const { return std::tan(vfovDegrees * kPi / 180 / 2); }
    double tanW() const { return tanH() * width / height; }

    // normalize((2 px / width - 1) tan_w u + (1 - 2 py / height) tan_h v - w)
    Vec3d direction(double px, double py) const {
        return normalize((2 * px / width - 1) * tanW() * u() +
                         (1 - 2 * py / height) * tanH() * v() - w());
    }

    PerspectiveCamera camera(float aperture = 0, float focusDistance = 1) const {
        return PerspectiveCamera(CameraFrame(Vec3(position), Vec3(lookAt), Vec3(up)),
                                 static_cast<float>(vfovDegrees), aperture, focusDistance);
    }
};

// An oblique camera: looking down and sideways, with an "up" that is not orthogonal to the view.
const CameraSpec kOblique{Vec3d(1, 2, 6), Vec3d(0, 0.5, -1), Vec3d(0.1, 1, 0), 40, 640, 480};
// The usual one: at +z looking at the origin, y up; right is +x.
const CameraSpec kStraight{Vec3d(0, 0, 5), Vec3d(0, 0, 0), Vec3d(0, 1, 0), 90, 200, 100};

const Vec2 kLensCentre(0.5f, 0.5f);

void expectPinholeRaysFollowTheFormula(const CameraSpec& spec) {
    const PerspectiveCamera camera = spec.camera();
    const Vec3 position(spec.position);
    // Pixel centres over the whole image, and its corners.
    for (int j = 0; j < spec.height; j += 7) {
        for (int i = 0; i < spec.width; i += 9) {
            const Ray ray =
                *camera.generateRay(static_cast<float>(i) + 0.5f, static_cast<float>(j) + 0.5f,
                                    spec.width, spec.height, kLensCentre);
            EXPECT_EQ(ray.origin, position);
            EXPECT_VEC3_NEAR(ray.direction, Vec3(spec.direction(i + 0.5, j + 0.5)), kTolerance)
                << "pixel " << i << ", " << j;
        }
    }
    const float w = static_cast<float>(spec.width), h = static_cast<float>(spec.height);
    for (const Vec2& corner : {Vec2(0, 0), Vec2(w, 0), Vec2(0, h), Vec2(w, h)}) {
        const Ray ray =
            *camera.generateRay(corner.x, corner.y, spec.width, spec.height, kLensCentre);
        EXPECT_VEC3_NEAR(ray.direction, Vec3(spec.direction(corner.x, corner.y)), kTolerance)
            << "corner " << corner.x << ", " << corner.y;
    }
}

TEST(CameraTest, PinholeRaysFollowTheContractFormula) {
    expectPinholeRaysFollowTheFormula(kOblique);
    expectPinholeRaysFollowTheFormula(kStraight);
}

TEST(CameraTest, CentreRayLooksAtTheTarget) {
    const Ray ray = *kOblique.camera().generateRay(320, 240, 640, 480, kLensCentre);
    EXPECT_VEC3_NEAR(ray.direction, Vec3(normalize(kOblique.lookAt - kOblique.position)),
                     kTolerance);
}

TEST(CameraTest, ImageEdgesAreAtHalfTheFieldOfView) {
    // kStraight: vfov 90, so the top edge is 45 degrees up; the image is twice as wide as high,
    // so the right edge is atan(2) to the right. y grows downwards in the image.
    const PerspectiveCamera camera = kStraight.camera();
    const float half = std::sqrt(0.5f);
    EXPECT_VEC3_NEAR(camera.generateRay(100, 0, 200, 100, kLensCentre)->direction,
                     Vec3(0, half, -half), kTolerance);
    EXPECT_VEC3_NEAR(camera.generateRay(100, 100, 200, 100, kLensCentre)->direction,
                     Vec3(0, -half, -half), kTolerance);
    const float root5 = std::sqrt(5.0f);
    EXPECT_VEC3_NEAR(camera.generateRay(200, 50, 200, 100, kLensCentre)->direction,
                     Vec3(2 / root5, 0, -1 / root5), kTolerance);
    EXPECT_VEC3_NEAR(camera.generateRay(0, 50, 200, 100, kLensCentre)->direction,
                     Vec3(-2 / root5, 0, -1 / root5), kTolerance);
}

TEST(CameraTest, SameImagePointAtAnyResolutionGivesTheSameRay) {
    const PerspectiveCamera camera = kOblique.camera();
    const Ray small = *camera.generateRay(10.5f, 20.25f, 64, 48, kLensCentre);
    const Ray large = *camera.generateRay(105, 202.5f, 640, 480, kLensCentre);
    EXPECT_VEC3_NEAR(small.direction, large.direction, kTolerance);
}

TEST(CameraTest, ZeroApertureIgnoresTheLensSample) {
    const PerspectiveCamera camera = kOblique.camera(0, 3);
    EXPECT_FALSE(camera.usesLensSample()) << "so that it is not drawn";
    EXPECT_TRUE(kOblique.camera(0.1f, 3).usesLensSample());
    Random random(61);
    for (int i = 0; i < 100; ++i) {
        const Vec2 lens(static_cast<float>(random.uniform()), static_cast<float>(random.uniform()));
        const Ray ray = *camera.generateRay(100.5f, 200.5f, 640, 480, lens);
        EXPECT_EQ(ray.origin, Vec3(kOblique.position));
        EXPECT_VEC3_NEAR(ray.direction, Vec3(kOblique.direction(100.5, 200.5)), kTolerance);
    }
}

// With a lens of radius `aperture`, every ray through an image point starts on the lens disc
// (in the u v plane around the position) and passes through the point where the pinhole ray
// meets the plane of focus, at focus_distance along -w.
TEST(CameraTest, ThinLensRaysStartOnTheLensAndMeetAtTheFocusPoint) {
    constexpr float kAperture = 0.25f, kFocusDistance = 4.5f;
    const PerspectiveCamera camera = kOblique.camera(kAperture, kFocusDistance);
    const Vec3d w = kOblique.w();
    Random random(62);
    double widest = 0;
    for (int i = 0; i < 2000; ++i) {
        const double px = random.uniform(0, 640), py = random.uniform(0, 480);
        const Vec2 lens(static_cast<float>(random.uniform()), static_cast<float>(random.uniform()));
        const Ray ray =
            *camera.generateRay(static_cast<float>(px), static_cast<float>(py), 640, 480, lens);

        const Vec3d pinhole = kOblique.direction(px, py);
        const Vec3d focusPoint = kOblique.position + (kFocusDistance / dot(pinhole, -w)) * pinhole;
        const Vec3d onLens = Vec3d(ray.origin) - kOblique.position;
        EXPECT_NEAR(dot(onLens, w), 0, 1e-6);  // in the lens plane
        EXPECT_LE(length(onLens), kAperture * (1 + 1e-6));
        widest = std::max(widest, length(onLens));
        EXPECT_NEAR(length(ray.direction), 1, kTolerance);
        // Distance from the focus point to the ray's line.
        const Vec3d toFocus = focusPoint - Vec3d(ray.origin);
        const Vec3d d = normalize(Vec3d(ray.direction));
        EXPECT_LT(length(toFocus - dot(toFocus, d) * d), 1e-5) << "ray " << i;
        EXPECT_GT(dot(toFocus, d), 0);  // ahead of the ray
    }
    EXPECT_GT(widest, 0.95 * kAperture);  // the samples cover the disc, not a smaller one
}

TEST(CameraTest, LensCentreSampleIsThePinholeRay) {
    const PerspectiveCamera camera = kOblique.camera(0.25f, 4.5f);
    const Ray ray = *camera.generateRay(123.5f, 45.5f, 640, 480, kLensCentre);
    EXPECT_EQ(ray.origin, Vec3(kOblique.position));
    EXPECT_VEC3_NEAR(ray.direction, Vec3(kOblique.direction(123.5, 45.5)), kTolerance);
}

}  // namespace
}  // namespace lancer
