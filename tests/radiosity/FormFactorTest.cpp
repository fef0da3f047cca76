// Form factors: the exact point-to-polygon formula against closed forms, the area form factors
// the solver's element-to-patch values add up to against the textbook values for unit squares,
// and reciprocity, without and with an occluder.

#include <gtest/gtest.h>

#include <cmath>

#include "RadiosityTestSupport.h"
#include "radiosity/FormFactor.h"
#include "radiosity/PatchMesher.h"
#include "sampling/Sampling.h"

namespace lancer::test {
namespace {

// A differential area at height h under the corner of a W x L rectangle parallel to it
// (Howell's catalogue, B-3): F = 1/(2 pi) [a / sqrt(1 + a^2) atan(b / sqrt(1 + a^2)) +
// b / sqrt(1 + b^2) atan(a / sqrt(1 + b^2))], a = W / h, b = L / h.
double underCorner(double W, double L, double h) {
    const double a = W / h, b = L / h;
    const double sa = std::sqrt(1 + a * a), sb = std::sqrt(1 + b * b);
    return (a / sa * std::atan(b / sa) + b / sb * std::atan(a / sb)) / (2 * std::numbers::pi);
}

TEST(FormFactorTest, PointToRectangleMatchesTheClosedForm) {
    for (const auto& [W, L, h] : {std::tuple{1.0, 1.0, 1.0}, {2.0, 0.5, 0.3}, {0.1, 5.0, 2.0}}) {
        const Vec3 p0(0, 0, static_cast<float>(h)),
            p1(static_cast<float>(W), 0, static_cast<float>(h)),
            p2(static_cast<float>(W), static_cast<float>(L), static_cast<float>(h)),
            p3(0, static_cast<float>(L), static_cast<float>(h));
        const double F = FormFactor::pointToTriangle(Vec3d(0, 0, 0), Vec3d(0, 0, 1), {p0, p1, p2}) +
                         FormFactor::pointToTriangle(Vec3d(0, 0, 0), Vec3d(0, 0, 1), {p0, p2, p3});
        EXPECT_NEAR(F, underCorner(W, L, h), 1e-6) << W << " x " << L << " at " << h;
    }
}

TEST(FormFactorTest, OnlyThePartInFrontOfThePointCounts) {
    // A triangle straddling the point's tangent plane counts as its upper half; one behind it
    // counts for nothing; a huge one in front covers almost the whole hemisphere.
    const Vec3d p(0, 0, 0), n(0, 0, 1);
    const double upper =
        FormFactor::pointToTriangle(p, n, {Vec3(-1, 1, 0), Vec3(1, 1, 0), Vec3(0, 1, 2)});
    const double whole =
        FormFactor::pointToTriangle(p, n, {Vec3(-1, 1, -2), Vec3(1, 1, -2), Vec3(0, 1, 2)});
    EXPECT_GT(upper, 0);
    EXPECT_NEAR(
        whole,
        FormFactor::pointToTriangle(p, n, {Vec3(-0.5f, 1, 0), Vec3(0.5f, 1, 0), Vec3(0, 1, 2)}),
        1e-6);
    EXPECT_EQ(FormFactor::pointToTriangle(p, n, {Vec3(-1, 1, -1), Vec3(1, 1, -1), Vec3(0, 1, -3)}),
              0);
    EXPECT_NEAR(FormFactor::pointToTriangle(
                    p, n, {Vec3(-1e4f, -1e4f, 1), Vec3(1e4f, -1e4f, 1), Vec3(0, 1e4f, 1)}),
                1, 1e-3);
}

// A point on the plane of a triangle facing the same way sees it edge-on: F = 0, also where
// rounding puts the point a hair in front of it inside its outline (where the contour integral
// gives 1, the triangle filling the hemisphere). A point 1 mm in front, facing it, still sees
// almost all of its hemisphere filled.
TEST(FormFactorTest, APointOnTheTrianglesPlaneSeesNothingOfIt) {
    // The front face of cornell-original's tall block: tilted, so that its points round off it.
    const Vec3 a(0.04f, 0, -0.09f), b(-0.53f, 0, 0.09f), up(0, 1.2f, 0);
    const std::array<Vec3, 3> triangle{a, b, b + up};
    const Vec3 n = normalize(cross(b - a, up));
    for (const double h : {0.0, 1e-9, 1e-7, -1e-9}) {
        for (const float s : {0.2f, 0.6f, 0.9f}) {
            const Vec3 inside = a + s * (b - a) + (0.5f * s) * up;  // rounded to float
            const Vec3d p = Vec3d(inside) + h * Vec3d(n);
            EXPECT_EQ(FormFactor::pointToSideOfTriangle(p, Vec3d(n), triangle, n, Side::Front), 0)
                << h << " " << s;
            EXPECT_EQ(FormFactor::pointToSideOfTriangleApprox(p, Vec3d(n), triangle, n, Side::Front,
                                                              0.5, 1.44),
                      0)
                << h << " " << s;
        }
    }
    const Vec3d near = Vec3d(a + 0.5f * (b - a) + 0.4f * up) + 1e-3 * Vec3d(n);
    EXPECT_GT(FormFactor::pointToSideOfTriangle(near, -Vec3d(n), triangle, n, Side::Front), 0.99);
}

TEST(FormFactorTest, TheFarFieldApproximationMatchesTheExactFormula) {
    // Triangles just beyond the far-field distance (kFarField times their longest edge), seen
    // head-on, tilted and off to the side: the approximation agrees with the exact formula.
    const std::array<Vec3, 3> triangle{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.3f, 0.8f, 0)};
    const Vec3 normal(0, 0, 1);
    const Vec3d centroid = (Vec3d(triangle[0]) + Vec3d(triangle[1]) + Vec3d(triangle[2])) / 3.0;
    const double area = 0.4, edge2 = 1;
    double worst = 0;
    for (const Vec3d& direction :
         {Vec3d(0, 0, 1), Vec3d(0.5, 0.2, 1), Vec3d(-0.8, 0.6, 0.4), Vec3d(0.9, -0.1, 0.3)}) {
        for (const double distance : {2.05, 2.5, 3.5}) {
            const Vec3d p = centroid + distance * normalize(direction);
            const Vec3d towards = normalize(centroid - p);
            for (const Vec3d& tilt :
                 {Vec3d(0, 0, 0), Vec3d(0.4, 0, 0), Vec3d(0, -0.3, 0.2), Vec3d(-0.2, 0.3, -0.3)}) {
                const Vec3d n = normalize(towards + tilt);
                const double exact =
                    FormFactor::pointToSideOfTriangle(p, n, triangle, normal, Side::Front);
                const double approx = FormFactor::pointToSideOfTriangleApprox(
                    p, n, triangle, normal, Side::Front, area, edge2);
                ASSERT_GT(exact, 0);
                worst = std::max(worst, std::abs(approx / exact - 1));
            }
        }
    }
    EXPECT_LT(worst, 5e-3);
}

// Two unit squares; elements of 1/32 make the area integral's quadrature error far below the
// tolerance (2e-4, about 0.1%).
struct SquarePair {
    Scene scene;
    RadiosityMesh mesh;
    std::vector<std::uint32_t> a, b;
};

SquarePair squares(const std::string& objects, const Vec3& normalA, const Vec3& normalB,
                   float elementSize = 1.0f / 32) {
    SquarePair pair{loadScene(objects, R"(, "radiosity": {"patch_size": 2, "element_size": )" +
                                           std::to_string(elementSize) + "}"),
                    {},
                    {},
                    {}};
    pair.mesh = PatchMesher(pair.scene, pair.scene.settings().radiosity).mesh();
    pair.a = patchesFacing(pair.mesh, normalA);
    pair.b = patchesFacing(pair.mesh, normalB);
    return pair;
}

TEST(FormFactorTest, ParallelUnitSquaresAtDistanceOne) {
    // Facing each other one unit apart: F = 0.19982 (Howell's catalogue, C-11).
    const SquarePair p = squares(square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)) + ", " +
                                     square(Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0)),
                                 Vec3(0, 0, 1), Vec3(0, 0, -1));
    ASSERT_EQ(p.a.size(), 2u);
    ASSERT_EQ(p.b.size(), 2u);
    EXPECT_NEAR(areaFormFactor(p.scene, p.mesh, p.a, p.b, 1), 0.19982, 2e-4);
    EXPECT_NEAR(areaFormFactor(p.scene, p.mesh, p.b, p.a, 1), 0.19982, 2e-4);
}

TEST(FormFactorTest, PerpendicularUnitSquaresSharingAnEdge) {
    // F = 0.20004 (Howell's catalogue, C-14). The integrand grows like log(1 / distance) at the
    // shared edge, which the elements' midpoint rule underestimates a little: 1e-3.
    const SquarePair p = squares(square(Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0)) + ", " +
                                     square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)),
                                 Vec3(0, 1, 0), Vec3(0, 0, 1));
    ASSERT_EQ(p.a.size(), 2u);
    ASSERT_EQ(p.b.size(), 2u);
    EXPECT_NEAR(areaFormFactor(p.scene, p.mesh, p.a, p.b, 1), 0.20004, 1e-3);
    EXPECT_NEAR(areaFormFactor(p.scene, p.mesh, p.b, p.a, 1), 0.20004, 1e-3);
}

TEST(FormFactorTest, NothingHidesTwoWallsOfACornerFromEachOther) {
    // The walls x = 1 and z = 1 of a room, meeting along its edge. The rays between elements near
    // that edge graze both walls; a ray's end point rounded an ulp behind its wall met the wall
    // just before it (at t = 0.9996), and the pair lost a ray of its visibility.
    const SquarePair p = squares(square(Vec3(1, 0, 1), Vec3(0, 1, 0), Vec3(0, 0, -1)) + ", " +
                                     square(Vec3(1, 0, 1), Vec3(-1, 0, 0), Vec3(0, 1, 0)),
                                 Vec3(-1, 0, 0), Vec3(0, 0, -1), 1.0f / 16);
    const FormFactor formFactor(p.scene);
    const auto nearTheEdge = [&](const std::vector<std::uint32_t>& patches) {
        std::vector<std::uint32_t> elements;
        for (std::uint32_t patch : patches)
            for (std::uint32_t e = p.mesh.patches[patch].firstElement;
                 e < p.mesh.patches[patch].firstElement + p.mesh.patches[patch].elementCount; ++e)
                if (std::max(1 - p.mesh.elements[e].centroid.x, 1 - p.mesh.elements[e].centroid.z) <
                    0.1f)
                    elements.push_back(e);
        return elements;
    };
    const std::vector<std::uint32_t> receivers = nearTheEdge(p.a), sources = nearTheEdge(p.b);
    ASSERT_GT(receivers.size(), 30u);
    ASSERT_GT(sources.size(), 30u);
    std::uint64_t rays = 0;
    int hidden = 0;
    for (std::uint32_t r : receivers)
        for (std::uint32_t s : sources) {
            const Element& source = p.mesh.elements[s];
            const Color visibility = formFactor.areaVisibility(
                p.mesh.elements[r], p.mesh.elements[r].corners, false, Side::Front, source.corners,
                p.mesh.patches[source.patch], Side::Front, 16, hashValues(r, s), rays);
            if (visibility.r < 1) ++hidden;
        }
    EXPECT_EQ(hidden, 0) << "of " << receivers.size() * sources.size() << " pairs";
}

TEST(FormFactorTest, RaysWeighAsMuchAsThePieceOfTheSourceTheyStandFor) {
    // A small floor element 1 in front of a unit wall, and a black strip 0.2 high at 0.9 that
    // hides the wall below 0.2 / 0.9 from it: 22% of the wall's area, but only the part seen
    // near the horizon, where cos cos / d^2 is small. F times the visibility must be the form
    // factor of the part left in view (the fraction of rays that get through took 22% off).
    const std::string objects =
        square(Vec3(-0.01f, 0, 0.01f), Vec3(0.02f, 0, 0), Vec3(0, 0, -0.02f)) + ", " +
        square(Vec3(-0.5f, 0, -1), Vec3(1, 0, 0), Vec3(0, 1, 0)) + ", " +
        square(Vec3(-2, 0, -0.9f), Vec3(4, 0, 0), Vec3(0, 0.2f, 0), "black");
    const SquarePair p = squares(objects, Vec3(0, 1, 0), Vec3(0, 0, 1), 4);
    ASSERT_EQ(p.a.size(), 2u);
    ASSERT_GE(p.b.size(), 2u);
    const FormFactor formFactor(p.scene);
    const Element& receiver = p.mesh.elements[p.mesh.patches[p.a[0]].firstElement];
    const Vec3d at(receiver.centroid), up(0, 1, 0);
    double seen = 0, whole = 0;
    std::uint64_t rays = 0;
    for (std::uint32_t patch : p.b) {
        if (p.mesh.patches[patch].corners[0].z > -0.95f) continue;  // the strip
        const std::array<Vec3, 3>& wall = p.mesh.patches[patch].corners;
        const double F = FormFactor::pointToTriangle(at, up, wall);
        const Color visibility =
            formFactor.areaVisibility(receiver, receiver.corners, false, Side::Front, wall,
                                      p.mesh.patches[patch], Side::Front, 4096, patch, rays);
        seen += F * visibility.r;
        whole += F;
    }
    // The wall above the shadow's edge, as seen from the element's centroid.
    const float edge = 0.2f * (1 - receiver.centroid.z) / (0.9f - receiver.centroid.z);
    const Vec3 a(-0.5f, edge, -1), b(0.5f, edge, -1), c(0.5f, 1, -1), d(-0.5f, 1, -1);
    const double exact = FormFactor::pointToTriangle(at, up, {a, b, c}) +
                         FormFactor::pointToTriangle(at, up, {a, c, d});
    ASSERT_LT(exact, 0.95 * whole);
    ASSERT_GT(exact, (1 - edge) * whole + 0.1 * whole);  // the area fraction would be far off
    EXPECT_NEAR(seen, exact, 0.01 * exact);
}

TEST(FormFactorTest, ReciprocityForUnequalPatches) {
    // A unit square and a 2 x 0.5 rectangle, tilted: A_i F_ij = A_j F_ji.
    const std::string objects = square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)) + ", " +
                                square(Vec3(-0.5f, 0.2f, 1.5f), Vec3(0, 0.5f, 0), Vec3(2, 0, 0.6f));
    const Vec3 tilted = normalize(cross(Vec3(0, 0.5f, 0), Vec3(2, 0, 0.6f)));
    const SquarePair p = squares(objects, Vec3(0, 0, 1), tilted);
    const double areaB = length(cross(Vec3(0, 0.5f, 0), Vec3(2, 0, 0.6f)));
    const double ab = areaFormFactor(p.scene, p.mesh, p.a, p.b, 1);
    const double ba = areaFormFactor(p.scene, p.mesh, p.b, p.a, 1);
    EXPECT_GT(ab, 0.05);
    EXPECT_NEAR(1 * ab, areaB * ba, 2e-3 * ab);
}

TEST(FormFactorTest, ReciprocityWithAnOccluderBetween) {
    // A black square half-way between the parallel squares, off-centre, hides part of each from
    // the other. Visibility is sampled (16 rays per element and patch over ~2000 elements), so
    // reciprocity holds to the sampling noise: 2% of F.
    const std::string objects =
        square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)) + ", " +
        square(Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0)) + ", " +
        square(Vec3(0.3f, 0.2f, 0.5f), Vec3(0.5f, 0, 0), Vec3(0, 0.5f, 0), "black");
    const SquarePair p = squares(objects, Vec3(0, 0, 1), Vec3(0, 0, -1));
    const double ab = areaFormFactor(p.scene, p.mesh, p.a, p.b, 16);
    const double ba = areaFormFactor(p.scene, p.mesh, p.b, p.a, 16);
    EXPECT_LT(ab, 0.19982 * 0.8);  // the occluder matters
    EXPECT_NEAR(ab, ba, 0.02 * ab);
}

}  // namespace
}  // namespace lancer::test
