// The torus: the roots of its quartic where they are known (through the hole, the equator from
// outside and from inside the tube, the nearest of four), its normals and uv, grazing rays at
// the silhouette and the inner rim against a brute-force march of the exact distance, the same
// answers at every scale, spawned rays that never find the wall they leave, samples uniform by
// area, and a tessellation of the right area whose probes find their own part of the surface.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "TestSupport.h"
#include "geometry/TessellationRequest.h"
#include "geometry/Torus.h"

namespace lancer {
namespace {

using test::Random;

constexpr float kTolerance = 1e-5f;

// R = 1, r = 0.25 about the y axis through the origin: the frame's first tangent is +x and its
// second -z, so u is the angle from +x towards -z, as on a sphere.
const Torus kTorus(Vec3(0), Vec3(0, 1, 0), 1, 0.25f, nullptr);

TEST(TorusTest, ARayDownTheAxisPassesThroughTheHole) {
    EXPECT_FALSE(kTorus.intersect({Vec3(0, 5, 0), Vec3(0, -1, 0)}, kInfinity));
    EXPECT_FALSE(kTorus.intersect({Vec3(0, -5, 0), Vec3(0, 1, 0)}, kInfinity));
    // Just inside the inner rim it meets the top of the tube.
    const std::optional<Hit> hit = kTorus.intersect({Vec3(0.8f, 5, 0), Vec3(0, -1, 0)}, kInfinity);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->p.y, std::sqrt(0.25f * 0.25f - 0.2f * 0.2f), kTolerance);
}

TEST(TorusTest, ARayInTheEquatorialPlaneMeetsTheNearestOfFourRoots) {
    // The four roots are at x = 1.25, 0.75, -0.75, -1.25.
    const std::optional<Hit> outer = kTorus.intersect({Vec3(5, 0, 0), Vec3(-1, 0, 0)}, kInfinity);
    ASSERT_TRUE(outer);
    EXPECT_NEAR(outer->t, 5 - 1.25f, kTolerance);
    EXPECT_VEC3_NEAR(outer->ng, Vec3(1, 0, 0), kTolerance);
    EXPECT_NEAR(outer->uv().x, 0, kTolerance);
    EXPECT_NEAR(outer->uv().y, 0, kTolerance) << "the outer equator";
    EXPECT_GT(dot(cross(outer->dpdu, outer->dpdv), outer->ng), 0) << "dpdu x dpdv points out";
    // From the hole two roots lie behind: the nearest ahead is the far side's inner rim.
    const std::optional<Hit> third =
        kTorus.intersect({Vec3(0.5f, 0, 0), Vec3(-1, 0, 0)}, kInfinity);
    ASSERT_TRUE(third);
    EXPECT_NEAR(third->t, 1.25f, kTolerance);
    EXPECT_VEC3_NEAR(third->ng, Vec3(1, 0, 0), kTolerance) << "the inner rim faces the axis";
    EXPECT_NEAR(third->uv().x, 0.5f, kTolerance);
    EXPECT_NEAR(third->uv().y, 0.5f, kTolerance) << "the inner equator";
    // tMax short of the first root: nothing.
    EXPECT_FALSE(kTorus.intersect({Vec3(5, 0, 0), Vec3(-1, 0, 0)}, 3.7f));
}

TEST(TorusTest, FromTheHoleAndFromInsideTheTubeTheRayMeetsTheWallAhead) {
    const std::optional<Hit> rim = kTorus.intersect({Vec3(0), Vec3(0, 0, 1)}, kInfinity);
    ASSERT_TRUE(rim);
    EXPECT_NEAR(rim->t, 0.75f, kTolerance);
    EXPECT_VEC3_NEAR(rim->ng, Vec3(0, 0, -1), kTolerance);
    // From the core circle: out through the outer wall, the top and the inner wall, leaving.
    for (const auto& [direction, t, normal] :
         {std::tuple{Vec3(1, 0, 0), 0.25f, Vec3(1, 0, 0)},
          {Vec3(0, 1, 0), 0.25f, Vec3(0, 1, 0)},
          {Vec3(-1, 0, 0), 0.25f, Vec3(-1, 0, 0)},
          {normalize(Vec3(1, 1, 0)), 0.25f, normalize(Vec3(1, 1, 0))}}) {
        const Ray ray{Vec3(1, 0, 0), direction};
        const std::optional<Hit> hit = kTorus.intersect(ray, kInfinity);
        ASSERT_TRUE(hit);
        EXPECT_NEAR(hit->t, t, kTolerance);
        EXPECT_VEC3_NEAR(hit->ng, normal, kTolerance);
        EXPECT_FALSE(hit->frontFace(ray)) << "out of the solid";
    }
    // Along the tube from inside (a tangent of the core circle): it meets the outer wall.
    const std::optional<Hit> along = kTorus.intersect({Vec3(1, 0, 0), Vec3(0, 0, -1)}, kInfinity);
    ASSERT_TRUE(along);
    EXPECT_NEAR(along->t, std::sqrt(1.25f * 1.25f - 1), kTolerance);
}

TEST(TorusTest, UvAndNormalsAtKnownPoints) {
    // The top of the tube at phi = pi / 2 (towards -z): (0, r, -R), normal +y, u = v = 1/4.
    const std::optional<Hit> top = kTorus.intersect({Vec3(0, 5, -1), Vec3(0, -1, 0)}, kInfinity);
    ASSERT_TRUE(top);
    EXPECT_NEAR(top->t, 4.75f, kTolerance);
    EXPECT_VEC3_NEAR(top->ng, Vec3(0, 1, 0), kTolerance);
    EXPECT_NEAR(top->uv().x, 0.25f, kTolerance);
    EXPECT_NEAR(top->uv().y, 0.25f, kTolerance);
    // |dp/du| = 2 pi (R + r cos theta) = 2 pi, |dp/dv| = 2 pi r.
    EXPECT_VEC3_NEAR(top->dpdu, Vec3(-2 * kPi, 0, 0), 1e-4f);
    EXPECT_VEC3_NEAR(top->dpdv, Vec3(0, 0, 2 * kPi * 0.25f), 1e-4f);
    // The bottom at phi = pi: (-R, -r, 0), v = 3/4.
    const std::optional<Hit> bottom = kTorus.intersect({Vec3(-1, -5, 0), Vec3(0, 1, 0)}, kInfinity);
    ASSERT_TRUE(bottom);
    EXPECT_VEC3_NEAR(bottom->ng, Vec3(0, -1, 0), kTolerance);
    EXPECT_NEAR(bottom->uv().x, 0.5f, kTolerance);
    EXPECT_NEAR(bottom->uv().y, 0.75f, kTolerance);
}

// The exact signed distance from the torus R, r about the unit axis through c, in double.
double signedDistance(const Vec3d& p, const Vec3d& c, const Vec3d& axis, double R, double r) {
    const Vec3d local = p - c;
    const double z = dot(local, axis);
    const double rho = length(local - z * axis);
    return std::hypot(rho - R, z) - r;
}

// The first crossing along the ray (direction of any length) by a brute-force march of the
// distance in double, which is 1-Lipschitz: steps of 0.9 |distance| (at least `floor`) cannot
// jump over the surface but where it is thinner than the floor, which is near tangency.
std::optional<double> marchedCrossing(const Ray& ray, const Vec3d& c, const Vec3d& axis, double R,
                                      double r, double reach) {
    const Vec3d o(ray.origin), d = normalize(Vec3d(ray.direction));
    const double speed = length(Vec3d(ray.direction));
    const double floor = 1e-7 * (R + r);
    const auto at = [&](double s) { return signedDistance(o + s * d, c, axis, R, r); };
    const double start = at(0);
    double s = 0, distance = start;
    while (s < reach) {
        const double next = s + std::max(0.9 * std::abs(distance), floor);
        const double nextDistance = at(next);
        if ((nextDistance < 0) != (start < 0)) {
            double lo = s, hi = next;
            for (int i = 0; i < 80; ++i) {
                const double mid = 0.5 * (lo + hi);
                ((at(mid) < 0) == (start < 0) ? lo : hi) = mid;
            }
            return 0.5 * (lo + hi) / speed;
        }
        s = next;
        distance = nextDistance;
    }
    return std::nullopt;
}

struct Placement {
    float scale;
    Vec3 offset;
};
constexpr std::array<Placement, 4> kPlacements{
    {{1, Vec3(0)}, {1e-3f, Vec3(0)}, {1e3f, Vec3(0)}, {1, Vec3(20, -10, 30)}}};

TEST(TorusTest, GrazingRaysAtTheSilhouetteAndTheInnerRimAgreeWithABruteForceMarch) {
    // A tilted torus; rays nearly tangent to it, at random points (the silhouette from outside,
    // the inner rim from the hole, and from inside the tube), passing within 1e-2 of tangency.
    const Vec3d axisD = normalize(Vec3d(0.3, 1, -0.2));
    for (const Placement& placement : kPlacements) {
        const float s = placement.scale;
        const Vec3 center = placement.offset + s * Vec3(0.1f, -0.2f, 0.3f);
        const double R = 1.0 * s, r = 0.4 * s;
        const Torus torus(center, Vec3(axisD), static_cast<float>(R), static_cast<float>(r),
                          nullptr);
        // The torus as lancer stores it: the axis rounded to float, then normalised.
        const Vec3d axis = normalize(Vec3d(Vec3(axisD)));
        const double R0 = static_cast<float>(R), r0 = static_cast<float>(r);
        Random random(23);
        int compared = 0, hits = 0;
        for (int i = 0; i < 2500; ++i) {
            // A point of the surface, its normal n and a tangent direction there.
            const double phi = random.uniform(0, 2 * 3.14159265358979323846);
            const double theta = random.uniform(0, 2 * 3.14159265358979323846);
            Vec3d t1, t2;
            coordinateSystem(axis, t1, t2);
            const Vec3d radial = std::cos(phi) * t1 + std::sin(phi) * t2;
            const Vec3d n = std::cos(theta) * radial + std::sin(theta) * axis;
            const Vec3d p = Vec3d(center) + (R0 + r0 * std::cos(theta)) * radial +
                            (r0 * std::sin(theta)) * axis;
            Vec3d a, b;
            coordinateSystem(n, a, b);
            const double turn = random.uniform(0, 2 * 3.14159265358979323846);
            const Vec3d tangent = std::cos(turn) * a + std::sin(turn) * b;
            const double offset = random.uniform(-1e-2, 1e-2) * s;
            const double back = random.uniform(0.5, 3) * s;
            const Ray ray{Vec3(p + offset * n - back * tangent), Vec3(tangent)};
            const double reach = 4 * s + back;
            const auto reference = marchedCrossing(ray, Vec3d(center), axis, R0, r0, reach);
            // Away from tangency: the same answer with the origin moved by 1e-4 either way.
            bool nearTangency = false;
            for (const double shift : {-1e-4, 1e-4}) {
                const Ray moved{Vec3(Vec3d(ray.origin) + (shift * s) * n), ray.direction};
                const auto other = marchedCrossing(moved, Vec3d(center), axis, R0, r0, reach);
                if (other.has_value() != reference.has_value() ||
                    (other && std::abs(*other - *reference) > 1e-2 * s))
                    nearTangency = true;
            }
            if (nearTangency) continue;
            ++compared;
            const std::optional<Hit> hit = torus.intersect(ray, kInfinity);
            ASSERT_EQ(hit.has_value(), reference.has_value())
                << "scale " << s << ", ray " << i << ": offset " << offset / s;
            if (!hit) continue;
            ++hits;
            EXPECT_NEAR(hit->t, *reference, 1e-5 * s) << "scale " << s << ", ray " << i;
            // The normal is the exact outward one at the hit.
            const Vec3d local = Vec3d(hit->p) - Vec3d(center);
            const double z = dot(local, axis);
            const Vec3d core = R0 * normalize(local - z * axis);
            // (Within the rounding of p to float, over the tube's radius.)
            EXPECT_VEC3_NEAR(Vec3d(hit->ng), normalize(local - core),
                             1e-5 + 1e-6 * maxComponent(abs(hit->p)) / r0);
        }
        EXPECT_GT(compared, 2000) << "scale " << s;
        EXPECT_GT(hits, 600) << "scale " << s;
        EXPECT_LT(hits, compared - 600) << "scale " << s;
    }
}

TEST(TorusTest, EveryScaleGivesTheSameAnswers) {
    Random random(29);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 origin = random.pointInBox(2);
        const Vec3 direction = random.unitVector();
        std::optional<Hit> unit;
        for (const float s : {1.0f, 1e-3f, 1e3f}) {
            const Torus torus(s * Vec3(0.1f, 0, -0.2f), Vec3(1, 2, 0.5f), s, 0.3f * s, nullptr);
            const std::optional<Hit> hit = torus.intersect({s * origin, direction}, kInfinity);
            if (s == 1) {
                unit = hit;
                continue;
            }
            ASSERT_EQ(hit.has_value(), unit.has_value()) << "ray " << i << " at scale " << s;
            if (!hit) continue;
            EXPECT_NEAR(hit->t / s, unit->t, 1e-5f * std::max(1.0f, unit->t));
            EXPECT_VEC3_NEAR(hit->ng, unit->ng, 1e-5f);
            EXPECT_NEAR(hit->uv().x, unit->uv().x, 1e-5f);
            EXPECT_NEAR(hit->uv().y, unit->uv().y, 1e-5f);
        }
    }
}

TEST(TorusTest, SpawnedRaysNeverFindTheWallTheyLeave) {
    // Each crossing of a closed surface alternates entering and leaving: a ray spawned outwards
    // must enter at its first hit, one spawned inwards must leave, at any scale and placement.
    for (const Placement& placement : kPlacements) {
        for (const float s : {placement.scale, placement.scale * 10}) {
            const Torus torus(placement.offset, Vec3(0.2f, 1, 0.4f), s, 0.45f * s, nullptr);
            Random random(31);
            int spawned = 0;
            for (int i = 0; i < 3000; ++i) {
                const Vec3 origin =
                    placement.offset + s * (random.pointInBox(1) + 4.0f * random.unitVector());
                const std::optional<Hit> hit = torus.intersect(
                    {origin, random.pointInBox(1.5f) * s + placement.offset - origin}, kInfinity);
                if (!hit) continue;
                for (const bool outwards : {true, false}) {
                    const Vec3 w = random.unitVectorOnSide(hit->ng, outwards);
                    if (std::abs(dot(w, hit->ng)) < 1e-4f) continue;
                    const Ray ray = hit->spawnRay(w);
                    ++spawned;
                    const std::optional<Hit> next = torus.intersect(ray, kInfinity);
                    if (!outwards) {
                        ASSERT_TRUE(next) << "out of a closed solid";
                    }
                    if (next) {
                        EXPECT_EQ(next->frontFace(ray), outwards)
                            << "scale " << s << ", ray " << i << " at t " << next->t;
                    }
                }
            }
            EXPECT_GT(spawned, 1000);
        }
    }
}

TEST(TorusTest, SamplesAreUniformByArea) {
    // R = 1, r = 0.6: the tube angle's density is (1 + 0.6 cos theta) / 2 pi, the outer half
    // holds more than the inner. Pearson's chi-square over 8 bins of theta and 4 of phi.
    const Torus torus(Vec3(0.3f, 0, 0), Vec3(0, 0, 1), 1, 0.6f, nullptr);
    EXPECT_NEAR(torus.area(0), 4 * kPi * kPi * 0.6f, 1e-5f);
    constexpr int kBins = 8, kSamples = 80000;
    std::array<int, kBins> thetaCounts{};
    std::array<int, 4> phiCounts{};
    Random random(37);
    for (int i = 0; i < kSamples; ++i) {
        const Vec2 u(static_cast<float>(random.uniform()), static_cast<float>(random.uniform()));
        const std::optional<ShapeSample> sample = torus.sample(0, u);
        ASSERT_TRUE(sample);
        EXPECT_FLOAT_EQ(sample->pdf, 1 / torus.area(0));
        const Vec3d local = Vec3d(sample->p) - Vec3d(0.3, 0, 0);
        const double rho = std::hypot(local.x, local.y);
        EXPECT_NEAR(std::hypot(rho - 1, local.z), 0.6, 1e-6) << "on the surface";
        EXPECT_VEC3_NEAR(Vec3d(sample->n),
                         normalize(local - Vec3d(local.x / rho, local.y / rho, 0)), 1e-5);
        double theta = std::atan2(local.z, rho - 1);
        if (theta < 0) theta += 2 * 3.14159265358979323846;
        double phi = std::atan2(local.y, local.x);
        if (phi < 0) phi += 2 * 3.14159265358979323846;
        ++thetaCounts[std::min(kBins - 1,
                               static_cast<int>(theta / (2 * 3.14159265358979323846) * kBins))];
        ++phiCounts[std::min(3, static_cast<int>(phi / (2 * 3.14159265358979323846) * 4))];
    }
    double chiSquare = 0;
    for (int bin = 0; bin < kBins; ++bin) {
        const double a = 2 * 3.14159265358979323846 * bin / kBins,
                     b = 2 * 3.14159265358979323846 * (bin + 1) / kBins;
        const double expected =
            kSamples * ((b - a) + 0.6 * (std::sin(b) - std::sin(a))) / (2 * 3.14159265358979323846);
        chiSquare += (thetaCounts[bin] - expected) * (thetaCounts[bin] - expected) / expected;
    }
    // The 99.9th percentile of chi-square with 7 degrees of freedom.
    EXPECT_LT(chiSquare, 24.32);
    // Uniform in theta would be far off: the outer and the inner bins differ by the ratio
    // (1 + 0.6 cos) of the ring's circumference.
    EXPECT_GT(thetaCounts[0], 3 * thetaCounts[kBins / 2]);
    double phiChiSquare = 0;
    for (const int count : phiCounts)
        phiChiSquare += (count - kSamples / 4.0) * (count - kSamples / 4.0) / (kSamples / 4.0);
    EXPECT_LT(phiChiSquare, 16.27) << "the 99.9th percentile with 3 degrees of freedom";
}

TEST(TorusTest, TheTessellationHasTheTorussAreaAndItsProbesFindTheirOwnSurface) {
    for (const float r : {0.25f, 0.8f}) {
        const Torus torus(Vec3(0.1f, 0.2f, 0.3f), Vec3(1, 1, 0), 1, r, nullptr);
        const Tessellation tessellation = torus.tessellate({0.1f, torus.bounds()});
        EXPECT_TRUE(tessellation.curved);
        EXPECT_GT(tessellation.probeDistance, 0);
        float area = 0;
        for (const auto& facet : tessellation.facets) {
            const Vec3 n =
                cross(facet.corners[1] - facet.corners[0], facet.corners[2] - facet.corners[0]);
            ASSERT_GT(length(n), 0) << "no facet of zero area";
            area += length(n) / 2;
            EXPECT_EQ(facet.primitive, 0u);
            // The probe radiosity sends from the facet's centre finds the surface just there,
            // facing the facet's way (counter-clockwise seen from outside).
            const Vec3 centre = (facet.corners[0] + facet.corners[1] + facet.corners[2]) / 3.0f;
            const Vec3 unit = normalize(n);
            const std::optional<Hit> probe =
                torus.intersect({centre + tessellation.probeDistance * unit, -unit},
                                2 * tessellation.probeDistance);
            ASSERT_TRUE(probe);
            EXPECT_LT(length(probe->p - centre), 0.05f * r);
            EXPECT_GT(dot(probe->ng, unit), 0.9f);
        }
        EXPECT_NEAR(area, 4 * kPi * kPi * r, 0.01f * 4 * kPi * kPi * r) << "r = " << r;
    }
}

TEST(TorusTest, TheBoundsHoldTheTorus) {
    const Torus torus(Vec3(1, 2, 3), Vec3(1, 2, -1), 2, 0.5f, nullptr);
    const Bounds3 box = torus.bounds();
    Random random(41);
    Vec3 lowest(kInfinity), highest(-kInfinity);
    for (int i = 0; i < 20000; ++i) {
        const std::optional<ShapeSample> s = torus.sample(
            0, Vec2(static_cast<float>(random.uniform()), static_cast<float>(random.uniform())));
        ASSERT_TRUE(s);
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(s->p[axis], box.min[axis]);
            EXPECT_LE(s->p[axis], box.max[axis]);
        }
        lowest = min(lowest, s->p);
        highest = max(highest, s->p);
    }
    // Tight: the samples come within 1% of the box's extent on every side.
    for (int axis = 0; axis < 3; ++axis) {
        const float extent = box.max[axis] - box.min[axis];
        EXPECT_LT(lowest[axis] - box.min[axis], 0.01f * extent);
        EXPECT_LT(box.max[axis] - highest[axis], 0.01f * extent);
    }
}

}  // namespace
}  // namespace lancer
