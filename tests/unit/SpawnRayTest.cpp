// Secondary rays spawned from a hit never find the surface they start on again (no shadow acne,
// no speckles), whatever the scene's scale or distance from the origin: Hit::spawnRay and
// Hit::spawnRayTo offset the origin by the hit point's error bound.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <tuple>

#include "IntersectInto.h"
#include "TestSupport.h"
#include "geometry/Plane.h"
#include "geometry/Sphere.h"
#include "geometry/Triangle.h"
#include "materials/Optics.h"
#include "math/Float.h"

namespace lancer {
namespace {

using test::Random;
using test::SceneFrame;
using test::Vec3L;

constexpr int kRayCount = 10000;

// Directions within this cosine of the surface's tangent plane run along the surface: a few
// float roundings of the dot product with the normal.
constexpr float kAlongSurfaceCosine = 1e-6f;

enum class ShapeKind { Sphere, Plane, Triangle };

// A shape placed in a scene frame, with what the test needs to know about its exact surface.
struct SurfaceUnderTest {
    std::unique_ptr<Shape> shape;
    // The exact signed distance of a point from the surface, positive on the side ng points to.
    std::function<long double(const Vec3&)> signedDistance;
    // A random ray that hits the surface (from either side).
    std::function<Ray(Random&)> rayTowardsSurface;
    // For the sphere: a ray entering it meets it again, on the far side.
    bool isClosed = false;
    Vec3 center;
    float radius = 0;
};

// A random point at a distance in [0.01, 10] (times the frame's scale) from `target`.
Vec3 originNear(const Vec3& target, const SceneFrame& frame, Random& random) {
    const float distance = frame.scale * static_cast<float>(std::pow(10.0, random.uniform(-2, 1)));
    return target + distance * random.unitVector();
}

SurfaceUnderTest makeSphere(const SceneFrame& frame) {
    SurfaceUnderTest s;
    s.center = frame.place(Vec3(0.3f, -0.2f, 0.5f));
    s.radius = 1.3f * frame.scale;
    s.shape = std::make_unique<Sphere>(s.center, s.radius, nullptr);
    s.isClosed = true;
    s.signedDistance = [center = s.center, radius = s.radius](const Vec3& p) {
        return length(test::toLong(p) - test::toLong(center)) - radius;
    };
    s.rayTowardsSurface = [frame, center = s.center, radius = s.radius](Random& random) {
        const Vec3 target = center + radius * random.unitVector();
        // Half of the rays start inside the sphere and hit it from within.
        const Vec3 origin = random.uniform() < 0.5
                                ? center + 0.9f * radius * random.unitVector() *
                                               static_cast<float>(random.uniform())
                                : originNear(target, frame, random);
        return Ray{origin, target - origin};
    };
    return s;
}

SurfaceUnderTest makePlane(const SceneFrame& frame) {
    SurfaceUnderTest s;
    const Vec3 point = frame.place(Vec3(0.2f, -0.5f, 0.1f));
    auto plane = std::make_unique<Plane>(point, Vec3(0.3f, 1, -0.4f), nullptr);
    const Vec3L normal = test::toLong(plane->normal());  // the plane of the float unit normal
    s.shape = std::move(plane);
    s.signedDistance = [point, normal](const Vec3& p) {
        return dot(test::toLong(p) - test::toLong(point), normal);
    };
    s.rayTowardsSurface = [frame, point, n = Vec3(normal)](Random& random) {
        // Anywhere within 10 (times the scale) of the plane's point, from either side.
        const Vec3 target = point + frame.scale * 10.0f * cross(n, random.unitVector());
        const Vec3 origin = originNear(target, frame, random);
        return Ray{origin, target - origin};
    };
    return s;
}

SurfaceUnderTest makeTriangle(const SceneFrame& frame) {
    SurfaceUnderTest s;
    const std::array<Vec3, 3> v{frame.place(Vec3(-1, -0.5f, 0.2f)),
                                frame.place(Vec3(1.2f, -0.3f, -0.4f)),
                                frame.place(Vec3(0.1f, 1.1f, 0.3f))};
    s.shape = std::make_unique<Triangle>(v, nullptr);
    const Vec3L normal = normalize(
        cross(test::toLong(v[1]) - test::toLong(v[0]), test::toLong(v[2]) - test::toLong(v[0])));
    s.signedDistance = [v0 = v[0], normal](const Vec3& p) {
        return dot(test::toLong(p) - test::toLong(v0), normal);
    };
    s.rayTowardsSurface = [frame, v](Random& random) {
        // A point well inside, so that rounding never makes the ray slip past an edge.
        const float b1 = static_cast<float>(random.uniform(0.02, 0.48));
        const float b2 = static_cast<float>(random.uniform(0.02, 0.48));
        const Vec3 target = (1 - b1 - b2) * v[0] + b1 * v[1] + b2 * v[2];
        const Vec3 origin = originNear(target, frame, random);
        return Ray{origin, target - origin};
    };
    return s;
}

SurfaceUnderTest makeSurface(ShapeKind kind, const SceneFrame& frame) {
    switch (kind) {
        case ShapeKind::Sphere:
            return makeSphere(frame);
        case ShapeKind::Plane:
            return makePlane(frame);
        default:
            return makeTriangle(frame);
    }
}

std::string kindName(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::Sphere:
            return "Sphere";
        case ShapeKind::Plane:
            return "Plane";
        default:
            return "Triangle";
    }
}

// A shape in a frame, random hits on it, and the checks of the rays spawned from them.
class SpawnRayFixture : public testing::Test {
protected:
    SpawnRayFixture(ShapeKind kind, const SceneFrame& frame)
        : frame_(frame), surface_(makeSurface(kind, frame_)), random_(1234) {}

    // A random hit on the surface, and the ray that found it.
    std::pair<Ray, Hit> randomHit() {
        for (;;) {
            const Ray ray = surface_.rayTowardsSurface(random_);
            Hit hit;
            if (test::intersectInto(*surface_.shape, ray, kInfinity, hit)) return {ray, hit};
        }
    }

    // A direction of random length: spawning must not depend on it.
    Vec3 randomLength(const Vec3& w) {
        return static_cast<float>(std::pow(10.0, random_.uniform(-3, 3))) * w;
    }

    // Checks the ray spawned from `hit` in direction `w`: its origin lies strictly on the side
    // w leaves towards, and it meets the surface again only where it really does, at the far
    // side of a closed shape.
    testing::AssertionResult spawnsCleanly(const Hit& hit, const Vec3& w) {
        const float cosine = dot(w, hit.ng);
        // Closer to the surface than the float dot product can resolve, a direction runs along
        // it: which side it leaves to is a matter of rounding (it may rightly meet a plane again
        // far away), and spawning cannot be judged.
        if (std::abs(cosine) < kAlongSurfaceCosine * length(w)) return testing::AssertionSuccess();
        const Ray ray = hit.spawnRay(w);
        const long double distance = surface_.signedDistance(ray.origin);
        if (!(cosine > 0 ? distance > 0 : distance < 0))
            return testing::AssertionFailure()
                   << "the spawned origin is on the wrong side of the surface (signed distance "
                   << static_cast<double>(distance) << ", cos " << cosine << ")";
        Hit again;
        const bool hitAgain = test::intersectInto(*surface_.shape, ray, kInfinity, again);
        if (!surface_.isClosed || cosine > 0) {
            if (hitAgain)
                return testing::AssertionFailure()
                       << "a ray leaving the surface hits it again at t = " << again.t << " (cos "
                       << cosine << ")";
            return testing::AssertionSuccess();
        }
        // Into the sphere: the next hit is the far side, where the exact roots say.
        const auto roots = test::sphereRoots(ray, surface_.center, surface_.radius);
        if (!hitAgain || !roots)
            return testing::AssertionFailure() << "a ray into the sphere does not leave it";
        return test::isWithinErrorBound(again.p, test::pointOnRay(ray, roots->second), again.pError)
               << " (the next hit is not the far side; cos " << cosine << ")";
    }

    // The same for a shadow ray from `hit` towards a point `target` on the side it leaves to.
    testing::AssertionResult shadowRayIsClear(const Hit& hit, const Vec3& target) {
        const Ray ray = hit.spawnRayTo(target);
        Hit blocker;
        if (test::intersectInto(*surface_.shape, ray, 1 - kShadowEpsilon, blocker))
            return testing::AssertionFailure()
                   << "the shadow ray is blocked by its own surface at t = " << blocker.t;
        return testing::AssertionSuccess();
    }

    SceneFrame frame_;
    SurfaceUnderTest surface_;
    Random random_;
};

class SpawnRayTest : public SpawnRayFixture,
                     public testing::WithParamInterface<std::tuple<ShapeKind, SceneFrame>> {
protected:
    SpawnRayTest() : SpawnRayFixture(std::get<0>(GetParam()), std::get<1>(GetParam())) {}
};

class SphereShadowRayTest : public SpawnRayFixture, public testing::WithParamInterface<SceneFrame> {
protected:
    SphereShadowRayTest() : SpawnRayFixture(ShapeKind::Sphere, GetParam()) {}
};

TEST_P(SpawnRayTest, RandomDirectionsOnBothSidesNeverReHitTheSurface) {
    for (int i = 0; i < kRayCount; ++i) {
        const auto [ray, hit] = randomHit();
        const bool arrivedOnFront = hit.frontFace(ray);
        // Reflection-like: back to the side the ray came from; transmission-like: through.
        const Vec3 reflected = random_.unitVectorOnSide(hit.ng, arrivedOnFront);
        const Vec3 transmitted = random_.unitVectorOnSide(hit.ng, !arrivedOnFront);
        ASSERT_TRUE(spawnsCleanly(hit, randomLength(reflected))) << "reflected, ray " << i;
        ASSERT_TRUE(spawnsCleanly(hit, randomLength(transmitted))) << "transmitted, ray " << i;
    }
}

TEST_P(SpawnRayTest, MirrorAndRefractedDirectionsNeverReHitTheSurface) {
    for (int i = 0; i < kRayCount; ++i) {
        const auto [ray, hit] = randomHit();
        const Vec3 wo = -normalize(ray.direction);
        const Vec3 n = hit.frontFace(ray) ? hit.ng : -hit.ng;  // on the arriving side
        ASSERT_TRUE(spawnsCleanly(hit, reflect(wo, n))) << "mirror, ray " << i;
        ASSERT_TRUE(spawnsCleanly(hit, -wo)) << "straight through, ray " << i;
        for (float eta : {1.5f, 1 / 1.5f}) {
            const std::optional<Vec3> refracted = refract(wo, n, eta);
            if (refracted) {
                ASSERT_TRUE(spawnsCleanly(hit, *refracted)) << "refracted, ray " << i;
            }
        }
    }
}

TEST_P(SpawnRayTest, ShadowRaysToLightsOffTheSurfaceAreNotBlockedByIt) {
    for (int i = 0; i < kRayCount; ++i) {
        const auto [ray, hit] = randomHit();
        // Lights outside the sphere; on either side of a plane or a triangle.
        const bool front = surface_.isClosed || random_.uniform() < 0.5;
        const float side = front ? 1.0f : -1.0f;
        // A light is clearly off the surface when it stands off the tangent plane at the hit by
        // more than the hit point's own uncertainty (twice its error bound along the normal):
        // nearer, it is on the surface as far as float arithmetic can tell.
        const long double uncertainty =
            2 * dot(abs(test::toLong(hit.ng)), test::toLong(hit.pError));
        Vec3 light;
        do {
            const float distance =
                frame_.scale * static_cast<float>(std::pow(10.0, random_.uniform(-2, 2)));
            light = hit.p + distance * random_.unitVectorOnSide(hit.ng, front);
        } while (!(side * dot(test::toLong(light) - test::toLong(hit.p), test::toLong(hit.ng)) >
                   uncertainty));
        ASSERT_TRUE(shadowRayIsClear(hit, light)) << "ray " << i;
    }
}

// The counterpart of ShadowRaysToLightsOffTheSurfaceAreNotBlockedByIt, to show that the same
// rays do see a blocker: the sphere's own far side.
TEST_P(SphereShadowRayTest, ShadowRaysThroughTheSphereAreBlockedByItsFarSide) {
    for (int i = 0; i < kRayCount; ++i) {
        const auto [ray, hit] = randomHit();
        const Vec3 inwards = random_.unitVectorOnSide(hit.ng, false);
        // Beyond the far side: the chord is 2 r cos, the light a little further on.
        const float chord = -2 * surface_.radius * dot(inwards, hit.ng);
        if (chord < 1e-2f * surface_.radius) continue;  // too grazing to tell the sides apart
        const Vec3 light = hit.p + (chord + 0.5f * surface_.radius) * inwards;
        Hit blocker;
        ASSERT_TRUE(test::intersectInto(*surface_.shape, hit.spawnRayTo(light), 1 - kShadowEpsilon,
                                        blocker))
            << "ray " << i;
    }
}

INSTANTIATE_TEST_SUITE_P(Frames, SphereShadowRayTest, testing::ValuesIn(test::kSceneFrames),
                         test::frameName);

std::string shapeAndFrameName(const testing::TestParamInfo<SpawnRayTest::ParamType>& param) {
    return kindName(std::get<0>(param.param)) + std::get<1>(param.param).name;
}

INSTANTIATE_TEST_SUITE_P(ShapesAndFrames, SpawnRayTest,
                         testing::Combine(testing::Values(ShapeKind::Sphere, ShapeKind::Plane,
                                                          ShapeKind::Triangle),
                                          testing::ValuesIn(test::kSceneFrames)),
                         shapeAndFrameName);

}  // namespace
}  // namespace lancer
