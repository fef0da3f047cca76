// The solver: furnaces (closed sphere and box of uniform albedo and emission, whose exact answer
// is known), convergence of progressive refinement, energy balance, adaptive subdivision where
// a shadow falls, and independence from the thread count.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "RadiosityTestSupport.h"
#include "radiosity/RadiositySolver.h"

namespace lancer::test {
namespace {

constexpr float kAlbedo = 0.6f;
constexpr float kEmission = 0.25f;

// A closed box [0, 1]^3 of inward-facing squares (their front, the emitting side, inside).
std::string closedBox(const std::string& material) {
    return square(Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), material) + ", " +  // floor
           square(Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), material) + ", " +  // ceiling
           square(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), material) + ", " +  // back
           square(Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0), material) + ", " +  // front
           square(Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), material) + ", " +  // left
           square(Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), material);          // right
}

Scene furnaceBox() {
    // "glow" (loadScene's): albedo kAlbedo, emission kEmission.
    return loadScene(closedBox("glow"), R"(, "radiosity": {"patch_size": 0.5, "threshold": 1e-4})");
}

TEST(RadiositySolverTest, ClosedBoxFurnaceGivesTheGeometricSeries) {
    // Every element sees the rest of the closed box (form factors summing to 1), whose radiosity
    // is B = pi Le + rho E everywhere: E = pi Le / (1 - rho) on the inner side of every element.
    Scene scene = furnaceBox();
    RadiositySolver solver(scene);
    const RadiositySolution solution = solver.solve();
    const float expected = kPi * kEmission / (1 - kAlbedo);
    ASSERT_GT(solver.mesh().elements.size(), 100u);
    for (const Element& e : solver.mesh().elements) {
        if (!e.isLeaf()) continue;
        EXPECT_NEAR(e.irradiance[0].r, expected, 0.005f * expected);
        EXPECT_NEAR(e.irradiance[1].r, 0, 1e-6f);  // nothing outside
    }
    // The solution's interpolated value, at the centre of the floor seen from above.
    const auto E = solution.irradiance(Vec3(0.5f, 0, 0.5f), Vec3(0, 1, 0), Vec3(0, 1, 0));
    ASSERT_TRUE(E);
    EXPECT_NEAR(E->g, expected, 0.005f * expected);
}

TEST(RadiositySolverTest, UnshotPowerFallsMonotonicallyBelowTheThreshold) {
    Scene scene = furnaceBox();
    RadiositySolver solver(scene);
    solver.solve();
    const std::vector<double>& history = solver.unshotHistory();
    ASSERT_GT(history.size(), 10u);
    for (std::size_t i = 1; i < history.size(); ++i)
        ASSERT_LE(history[i], history[i - 1] * (1 + 1e-6)) << "shot " << i;
    EXPECT_LE(history.back(), 1e-4 * history.front());
    EXPECT_GT(history[history.size() - 2], 1e-4 * history.front());  // it stopped right there
}

TEST(RadiositySolverTest, EnergyBalanceInAClosedBox) {
    // What the emitters put in is what the surfaces absorb, (1 - rho) E A summed, plus what is
    // left unshot.
    Scene scene = furnaceBox();
    RadiositySolver solver(scene);
    const RadiositySolution solution = solver.solve();
    double absorbed = 0;
    for (const Element& e : solver.mesh().elements)
        if (e.isLeaf()) absorbed += (1 - kAlbedo) * e.irradiance[0].average() * e.area;
    const double emitted = kPi * kEmission * 6;
    EXPECT_NEAR(absorbed + solution.statistics().residualPower, emitted, 2e-3 * emitted);
}

TEST(RadiositySolverTest, ClosedSphereFurnace) {
    // The camera-free version of the sphere furnace: every element's inner irradiance is
    // pi Le / (1 - rho), the sphere being tessellated into a closed convex polyhedron.
    Scene scene = loadScene(R"({"type": "sphere", "center": [0.5, 0.5, 0.5], "radius": 1,
                                "material": "glow"})",
                            R"(, "radiosity": {"threshold": 1e-4, "patch_size": 1})");
    RadiositySolver solver(scene);
    solver.solve();
    const float expected = kPi * kEmission / (1 - kAlbedo);
    for (const Element& e : solver.mesh().elements)
        if (e.isLeaf()) {
            EXPECT_NEAR(e.irradiance[1].b, expected, 0.005f * expected);
        }
}

// A floor lit by a point light above it, with a small black square in between: a shadow.
Scene shadowedFloor(int levels) {
    return loadScene(square(Vec3(-2, 0, 2), Vec3(4, 0, 0), Vec3(0, 0, -4)) + ", " +
                         square(Vec3(-0.3f, 1, 0.3f), Vec3(0.6f, 0, 0), Vec3(0, 0, -0.6f), "black"),
                     R"(, "lights": [{"type": "point", "position": [0, 3, 0], "intensity": 10}],
                         "radiosity": {"patch_size": 1, "subdivision_levels": )" +
                         std::to_string(levels) + "}");
}

TEST(RadiositySolverTest, AdaptiveSubdivisionRefinesTheShadowBoundary) {
    Scene coarse = shadowedFloor(0), refined = shadowedFloor(3);
    RadiositySolver coarseSolver(coarse), refinedSolver(refined);
    const RadiositySolution a = coarseSolver.solve(), b = refinedSolver.solve();
    EXPECT_GT(b.statistics().elements, a.statistics().elements + 20);
    // The finest elements gather near the shadow's edge (|x| or |z| about 0.9 on the floor:
    // the square's edge 0.3 projected from the light at height 3 onto the floor, 3 / 2 times
    // further), not out where the floor is smoothly lit.
    int nearEdge = 0, farAway = 0;
    for (const Element& e : refinedSolver.mesh().elements) {
        if (!e.isLeaf() || e.level < 3 || e.normal.y < 0.5f) continue;
        const float edge = std::max(std::abs(e.centroid.x), std::abs(e.centroid.z));
        (std::abs(edge - 0.45f) < 0.4f ? nearEdge : farAway) += 1;
    }
    EXPECT_GT(nearEdge, 0);
    EXPECT_GE(nearEdge, 4 * farAway);
    // In the umbra, nothing; just outside, the light's E = I cos / d^2.
    const auto dark = b.irradiance(Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 0));
    const auto lit = b.irradiance(Vec3(1.5f, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 0));
    ASSERT_TRUE(dark && lit);
    EXPECT_LT(dark->r, 1e-3f);
    const float d2 = 1.5f * 1.5f + 9;
    EXPECT_NEAR(lit->r, 10 * (3 / std::sqrt(d2)) / d2, 0.05f * 10 * (3 / std::sqrt(d2)) / d2);
}

TEST(RadiositySolverTest, SameSolutionWhateverTheThreadCount) {
    const auto solve = [](int threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                        static_cast<std::size_t>(threads));
        Scene scene = shadowedFloor(2);
        RadiositySolver solver(scene);
        solver.solve();
        std::vector<Color> values;
        for (const Element& e : solver.mesh().elements)
            values.push_back(e.irradiance[0]);
        return values;
    };
    EXPECT_TRUE(solve(1) == solve(2));
}

}  // namespace
}  // namespace lancer::test
