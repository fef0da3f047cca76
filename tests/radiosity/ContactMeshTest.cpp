// Meshing along contact lines: a box standing on a surface (a floor, or a wall with the box turned
// about the wall's normal) leaves no element across its footprint's edges and none under it, the
// surface's meshed area is its own minus the footprint, surfaces nothing stands on are meshed as
// before, and the irradiance at the foot of a block matches the one found by tracing rays.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "RadiosityTestSupport.h"
#include "geometry/ConvexPolygon.h"
#include "radiosity/ContactCutter.h"
#include "radiosity/HierarchicalRadiosity.h"
#include "radiosity/PatchMesher.h"

namespace lancer::test {
namespace {

const std::string kSettings = R"(, "radiosity": {"patch_size": 0.5, "method": "hierarchical"})";

// The elements (all of them leaves, as the mesher makes them) of the patches lying in the plane
// through `point` with normal `normal`, facing it.
std::vector<std::array<Vec3, 3>> elementsOn(const RadiosityMesh& mesh, const Vec3& point,
                                            const Vec3& normal) {
    std::set<std::uint32_t> patches;
    for (const std::uint32_t p : patchesFacing(mesh, normal))
        if (std::abs(dot(mesh.patches[p].corners[0] - point, normal)) < 1e-5f) patches.insert(p);
    std::vector<std::array<Vec3, 3>> elements;
    for (const Element& e : mesh.elements)
        if (patches.count(e.patch)) elements.push_back(e.corners);
    return elements;
}

double area(const std::vector<Vec3d>& polygon) {
    Vec3d doubled(0);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
        doubled += cross(polygon[i] - polygon[0], polygon[i + 1] - polygon[0]);
    return 0.5 * length(doubled);
}

// The area of a triangle inside a convex polygon of its plane.
double overlap(const std::array<Vec3, 3>& triangle, const std::vector<Vec3>& footprint,
               const Vec3& normal) {
    std::vector<Vec3d> inside{Vec3d(triangle[0]), Vec3d(triangle[1]), Vec3d(triangle[2])};
    Vec3d centre(0);
    for (const Vec3& p : footprint)
        centre += Vec3d(p) / static_cast<double>(footprint.size());
    for (std::size_t i = 0; i < footprint.size() && !inside.empty(); ++i) {
        const Vec3d a(footprint[i]), b(footprint[(i + 1) % footprint.size()]);
        Vec3d inward = normalize(cross(Vec3d(normal), b - a));
        if (dot(inward, centre - a) < 0) inward = -inward;
        inside = clipPolygon(inside, inward, dot(inward, a));
    }
    return inside.empty() ? 0 : area(inside);
}

// A box standing on a 4 x 4 square centred on `centre`: no element of the square overlaps the
// footprint (none crosses its edges, none lies under it), and the square's elements cover its
// area less the footprint's.
void expectMeshedAroundFootprint(const Scene& scene, const Vec3& centre, const Vec3& normal,
                                 const std::vector<Vec3>& footprint) {
    const RadiosityMesh mesh = PatchMesher(scene, scene.settings().radiosity).mesh();
    const std::vector<std::array<Vec3, 3>> elements = elementsOn(mesh, centre, normal);
    ASSERT_GT(elements.size(), 100u);
    double meshed = 0;
    for (const auto& e : elements) {
        const double elementArea = area({Vec3d(e[0]), Vec3d(e[1]), Vec3d(e[2])});
        meshed += elementArea;
        // Nothing wider than the rounding of the corners (about 1e-7) along its sides.
        const double perimeter = length(e[1] - e[0]) + length(e[2] - e[1]) + length(e[0] - e[2]);
        EXPECT_LE(overlap(e, footprint, normal), 1e-6 * perimeter)
            << "element at " << e[0].x << ", " << e[0].y << ", " << e[0].z;
    }
    std::vector<Vec3d> footprintPolygon;
    for (const Vec3& p : footprint)
        footprintPolygon.push_back(Vec3d(p));
    EXPECT_NEAR(meshed, 16 - area(footprintPolygon), 1e-4);
}

TEST(ContactMeshTest, BoxOnAFloorLeavesNoElementAcrossOrUnderItsFootprint) {
    const Scene scene = loadScene(
        square(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0)) +
            R"(, {"type": "box", "min": [-0.5, 0, -0.3], "max": [0.4, 1, 0.6], "material": "white"})",
        kSettings);
    expectMeshedAroundFootprint(
        scene, Vec3(0), Vec3(0, 1, 0),
        {Vec3(-0.5f, 0, -0.3f), Vec3(0.4f, 0, -0.3f), Vec3(0.4f, 0, 0.6f), Vec3(-0.5f, 0, 0.6f)});
}

TEST(ContactMeshTest, BoxTurnedOnAWallLeavesNoElementAcrossOrUnderItsFootprint) {
    // The wall x = 0 faces +x; the box stands on it, turned 30 degrees about the x axis.
    const Scene scene =
        loadScene(square(Vec3(0, -2, -2), Vec3(0, 4, 0), Vec3(0, 0, 4)) +
                      R"(, {"type": "box", "min": [0, -0.4, -0.4], "max": [0.8, 0.4, 0.4],
                  "transform": {"rotate": [1, 0, 0, 30]}, "material": "white"})",
                  kSettings);
    std::vector<Vec3> footprint;
    const float c = std::cos(kPi / 6), s = std::sin(kPi / 6);
    for (const auto& [y, z] : {std::pair{-0.4f, -0.4f}, {0.4f, -0.4f}, {0.4f, 0.4f}, {-0.4f, 0.4f}})
        footprint.push_back(Vec3(0, c * y - s * z, s * y + c * z));
    expectMeshedAroundFootprint(scene, Vec3(0), Vec3(1, 0, 0), footprint);
}

TEST(ContactMeshTest, SurfacesWithoutContactsAreMeshedAsBefore) {
    // A box floating above the floor cuts nothing: the floor's elements are those of the floor
    // alone, bit for bit, and so are the ones of a wall touched only along its border.
    const std::string floor = square(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0));
    const std::string wall = square(Vec3(-2, 0, -2), Vec3(4, 0, 0), Vec3(0, 4, 0));
    const Scene alone = loadScene(floor + ", " + wall, kSettings);
    const Scene withBox = loadScene(
        floor + ", " + wall +
            R"(, {"type": "box", "min": [-0.5, 0.1, -0.3], "max": [0.4, 1, 0.6], "material": "white"})",
        kSettings);
    const RadiosityMesh before = PatchMesher(alone, alone.settings().radiosity).mesh();
    const RadiosityMesh after = PatchMesher(withBox, withBox.settings().radiosity).mesh();
    for (const Vec3& normal : {Vec3(0, 1, 0), Vec3(0, 0, 1)}) {
        const auto expected = elementsOn(before, Vec3(-2, 0, -2), normal);
        const auto found = elementsOn(after, Vec3(-2, 0, -2), normal);
        ASSERT_GT(expected.size(), 100u);
        EXPECT_EQ(found, expected);
    }
}

// A right triangle of the plane y = 0, facing +y, as the cutter takes it.
const std::vector<Vec3d> kTriangle{Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(0, 0, -1)};
const Vec3d kUp(0, 1, 0);

TEST(ContactMeshTest, FacetsTouchingATrianglesSidesOrOffItsPlaneDoNotCutIt) {
    const std::array<Vec3, 3> triangle{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, -1)};
    const ContactCutter cutter(
        {{{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5f, 1, 0)}, 1},           // on its side
         {{Vec3(0.5f, 0, 0), Vec3(0.5f, 0, 1), Vec3(0.5f, 1, 0.5f)}, 1},  // outside, touching
         {{Vec3(0.2f, 0.01f, -0.1f), Vec3(0.2f, 0.01f, -0.5f), Vec3(0.2f, 1, -0.3f)}, 1},  // above
         {triangle, 1}},                                                                   // itself
        1e-4f);
    EXPECT_TRUE(cutter.cut(kTriangle, kUp).polygons.empty());
}

TEST(ContactMeshTest, AFacetStandingOnATriangleOrSunkInItCutsItAlongTheLine) {
    // Standing on it along x = 0.2 from z = 0.5 to -0.3, or sunk through it along x = 0.3: the
    // line cuts the whole triangle in two.
    for (const std::array<Vec3, 3>& facet :
         {std::array<Vec3, 3>{Vec3(0.2f, 0, 0.5f), Vec3(0.2f, 0, -0.3f), Vec3(0.2f, 1, 0)},
          std::array<Vec3, 3>{Vec3(0.3f, -0.05f, 0.5f), Vec3(0.3f, -0.05f, -0.3f),
                              Vec3(0.3f, 1, 0)}}) {
        const ContactCutter cutter({{facet, 2}}, 1e-4f);
        const ContactCutter::Pieces pieces = cutter.cut(kTriangle, kUp);
        ASSERT_EQ(pieces.polygons.size(), 2u);
        EXPECT_EQ(pieces.reach, 2);
        EXPECT_NEAR(area(pieces.polygons[0]) + area(pieces.polygons[1]), 0.5, 1e-7);
    }
}

// The twelve facets of the box [lo, hi], with the box's size as their reach.
std::vector<ContactCutter::Facet> boxFacets(const Vec3& lo, const Vec3& hi) {
    const auto corner = [&](int i) {
        return Vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    };
    // Each face's corners in order around it, as indices into the box's corners.
    const std::array<std::array<int, 4>, 6> faces{
        {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}}};
    std::vector<ContactCutter::Facet> facets;
    for (const auto& [a, b, c, d] : faces) {
        facets.push_back({{corner(a), corner(b), corner(c)}, length(hi - lo)});
        facets.push_back({{corner(a), corner(c), corner(d)}, length(hi - lo)});
    }
    return facets;
}

TEST(ContactCutterTest, CuttingReachIsWhatCutFindsWithoutThePieces) {
    // A 2 x 2 floor facing +y, as a square, its two triangles and its four quarters.
    const std::vector<Vec3d> square{Vec3d(-1, 0, 1), Vec3d(1, 0, 1), Vec3d(1, 0, -1),
                                    Vec3d(-1, 0, -1)};
    const std::vector<std::vector<Vec3d>> polygons{
        square,
        {square[0], square[1], square[2]},
        {square[0], square[2], square[3]},
        {Vec3d(-1, 0, 1), Vec3d(0, 0, 1), Vec3d(0, 0, 0), Vec3d(-1, 0, 0)},
        {Vec3d(0, 0, 1), Vec3d(1, 0, 1), Vec3d(1, 0, 0), Vec3d(0, 0, 0)},
        {Vec3d(0, 0, 0), Vec3d(1, 0, 0), Vec3d(1, 0, -1), Vec3d(0, 0, -1)},
        {Vec3d(-1, 0, 0), Vec3d(0, 0, 0), Vec3d(0, 0, -1), Vec3d(-1, 0, -1)}};
    const auto join = [](std::vector<ContactCutter::Facet> a,
                         const std::vector<ContactCutter::Facet>& b) {
        a.insert(a.end(), b.begin(), b.end());
        return a;
    };
    const Vec3 blockLo(-0.3f, 0, -0.2f), blockHi(0.4f, 0.5f, 0.3f);
    const Vec3 sunkLo(-0.3f, -0.05f, -0.2f);
    const Vec3 tallLo(-0.8f, 0, 0.5f), tallHi(-0.6f, 2, 0.7f);
    const std::vector<ContactCutter::Facet> block = boxFacets(blockLo, blockHi);
    // Two panels standing along the line z = 0.5: the tall one counts though the small one's
    // cut already runs along its base.
    const ContactCutter::Facet smallPanel{
        {Vec3(-0.5f, 0, 0.5f), Vec3(-0.4f, 0, 0.5f), Vec3(-0.45f, 0.2f, 0.5f)}, 0.3f};
    const ContactCutter::Facet tallPanel{
        {Vec3(0.3f, 0, 0.5f), Vec3(0.4f, 0, 0.5f), Vec3(0.35f, 1.5f, 0.5f)}, 2};
    struct Configuration {
        const char* name;
        std::vector<ContactCutter::Facet> facets;
        std::optional<float> reach;  // the square's
    };
    const std::vector<Configuration> configurations{
        {"a block standing on the floor", block, length(blockHi - blockLo)},
        {"a block sunk into it", boxFacets(sunkLo, blockHi), length(blockHi - sunkLo)},
        {"two blocks: the larger reach", join(block, boxFacets(tallLo, tallHi)),
         length(tallHi - tallLo)},
        {"two panels along one line, the small one first", {smallPanel, tallPanel}, 2},
        {"two panels along one line, the tall one first", {tallPanel, smallPanel}, 2},
        {"a block floating above it", boxFacets(blockLo + Vec3(0, 0.1f, 0), blockHi), {}},
        {"a block beside it along its side",
         boxFacets(Vec3(1, 0, -0.5f), Vec3(1.5f, 0.5f, 0.5f)),
         {}},
        {"a block touching its corner", boxFacets(Vec3(1, 0, 1), Vec3(1.3f, 0.3f, 1.3f)), {}}};
    for (const Configuration& configuration : configurations) {
        SCOPED_TRACE(configuration.name);
        const ContactCutter cutter(configuration.facets, 1e-4f);
        for (std::size_t i = 0; i < polygons.size(); ++i) {
            SCOPED_TRACE("polygon " + std::to_string(i));
            const ContactCutter::Pieces pieces = cutter.cut(polygons[i], kUp);
            EXPECT_EQ(cutter.cuttingReach(polygons[i], kUp),
                      pieces.polygons.empty() ? std::nullopt : std::optional(pieces.reach));
        }
        EXPECT_EQ(cutter.cuttingReach(square, kUp), configuration.reach);
    }
}

TEST(ContactMeshTest, IrradianceAtTheFootOfABlockMatchesTracedRays) {
    // A black block on a white floor under a large lamp: the floor's irradiance is the lamp's
    // alone (the block and the lamp reflect nothing), found here by rays to a fine grid of points
    // of the lamp. Elements straddling the block's base made it 4-10% too bright here.
    const float le = 0.25f;  // the "lamp" material's radiance
    const Scene scene =
        loadScene(square(Vec3(-2, 0, -2), Vec3(0, 0, 4), Vec3(4, 0, 0)) + ", " +
                      square(Vec3(-2, 2, -2), Vec3(4, 0, 0), Vec3(0, 0, 4), "lamp") +
                      R"(, {"type": "box", "min": [-0.5, 0, -0.5],
                                            "max": [0.5, 1, 0.5], "material": "black"})",
                  R"(, "radiosity": {"method": "hierarchical", "patch_size": 0.25,
                                     "element_size": 0.0625, "subdivision_levels": 1})");
    HierarchicalRadiosity solver(scene);
    const std::optional<RadiositySolution> solution = solver.solve({}, nullptr);
    ASSERT_TRUE(solution);
    const Vec3 up(0, 1, 0);
    constexpr int kGrid = 200;
    const float cell = 4.0f / kGrid;
    for (const float distance : {0.03f, 0.1f})
        for (const float z : {-0.3f, 0.0f, 0.3f}) {
            const Vec3 p(0.5f + distance, 0, z);
            double traced = 0;
            for (int i = 0; i < kGrid; ++i)
                for (int j = 0; j < kGrid; ++j) {
                    const Vec3 q(-2 + (static_cast<float>(i) + 0.5f) * cell, 2,
                                 -2 + (static_cast<float>(j) + 0.5f) * cell);
                    const Vec3 d = q - p;
                    const float r2 = lengthSquared(d);
                    const Vec3 origin = p + 1e-4f * up;
                    if (scene.occluded(Ray{origin, q - origin}, 0.999f)) continue;
                    traced += le * (d.y * d.y) / (r2 * r2) * cell * cell;
                }
            const std::optional<Color> found = solution->irradiance(p, up, up);
            ASSERT_TRUE(found);
            EXPECT_NEAR(found->g, traced, 0.03 * traced) << "at x = " << p.x << ", z = " << p.z;
        }
}

}  // namespace
}  // namespace lancer::test
