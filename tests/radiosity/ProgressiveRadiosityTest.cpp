// The solver: furnaces (closed sphere and box of uniform albedo and emission, whose exact answer
// is known), convergence of progressive refinement, energy balance, adaptive subdivision where
// a shadow falls, independence from the thread count, and the progress reports and cancellation
// that lancer --window and Ctrl-C use.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <atomic>
#include <cmath>

#include "RadiosityTestSupport.h"
#include "radiosity/ProgressiveRadiosity.h"

namespace lancer::test {
namespace {

constexpr float kAlbedo = 0.6f;
constexpr float kEmission = 0.25f;

Scene furnaceBox() {
    // "glow" (loadScene's): albedo kAlbedo, emission kEmission.
    return loadScene(closedBox("glow"), R"(, "radiosity": {"patch_size": 0.5, "threshold": 1e-4})");
}

TEST(ProgressiveRadiosityTest, ClosedBoxFurnaceGivesTheGeometricSeries) {
    // Every element sees the rest of the closed box (form factors summing to 1), whose radiosity
    // is B = pi Le + rho E everywhere: E = pi Le / (1 - rho) on the inner side of every element.
    Scene scene = furnaceBox();
    ProgressiveRadiosity solver(scene);
    const RadiositySolution solution = solver.solve();
    const float expected = kPi * kEmission / (1 - kAlbedo);
    ASSERT_GT(solver.mesh().elements.size(), 100u);
    for (const Element& e : solver.mesh().elements) {
        if (!e.isLeaf()) continue;
        EXPECT_NEAR(e.irradiance[0].r, expected, 0.005f * expected);
        EXPECT_NEAR(e.irradiance[1].r, 0, 1e-6f);  // nothing outside
    }
    // The solution's interpolated value, at the centre of the floor seen from above, and its
    // part not straight from the emitters (the walls' pi Le over the whole hemisphere).
    const Vec3 up(0, 1, 0);
    const auto E = solution.irradiance(Vec3(0.5f, 0, 0.5f), up, up);
    const auto reflected =
        solution.irradiance(Vec3(0.5f, 0, 0.5f), up, up, RadiositySolution::Part::Indirect);
    ASSERT_TRUE(E && reflected);
    EXPECT_NEAR(E->g, expected, 0.005f * expected);
    EXPECT_NEAR(reflected->g, kAlbedo * expected, 0.005f * expected);
}

TEST(ProgressiveRadiosityTest, UnshotPowerFallsMonotonicallyBelowTheThreshold) {
    Scene scene = furnaceBox();
    ProgressiveRadiosity solver(scene);
    solver.solve();
    const std::vector<double>& history = solver.unshotHistory();
    ASSERT_GT(history.size(), 10u);
    for (std::size_t i = 1; i < history.size(); ++i)
        ASSERT_LE(history[i], history[i - 1] * (1 + 1e-6)) << "shot " << i;
    EXPECT_LE(history.back(), 1e-4 * history.front());
    EXPECT_GT(history[history.size() - 2], 1e-4 * history.front());  // it stopped right there
}

TEST(ProgressiveRadiosityTest, EnergyBalanceInAClosedBox) {
    // What the emitters put in is what the surfaces absorb, (1 - rho) E A summed, plus what is
    // left unshot.
    Scene scene = furnaceBox();
    ProgressiveRadiosity solver(scene);
    const RadiositySolution solution = solver.solve();
    double absorbed = 0;
    for (const Element& e : solver.mesh().elements)
        if (e.isLeaf()) absorbed += (1 - kAlbedo) * e.irradiance[0].average() * e.area;
    const double emitted = kPi * kEmission * 6;
    EXPECT_NEAR(absorbed + solution.statistics().residualPower, emitted, 2e-3 * emitted);
}

TEST(ProgressiveRadiosityTest, ClosedSphereFurnace) {
    // The camera-free version of the sphere furnace: every element's inner irradiance is
    // pi Le / (1 - rho), the sphere being tessellated into a closed convex polyhedron.
    Scene scene = loadScene(R"({"type": "sphere", "center": [0.5, 0.5, 0.5], "radius": 1,
                                "material": "glow"})",
                            R"(, "radiosity": {"threshold": 1e-4, "patch_size": 1})");
    ProgressiveRadiosity solver(scene);
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

TEST(ProgressiveRadiosityTest, AdaptiveSubdivisionRefinesTheShadowBoundary) {
    Scene coarse = shadowedFloor(0), refined = shadowedFloor(3);
    ProgressiveRadiosity coarseSolver(coarse), refinedSolver(refined);
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

TEST(ProgressiveRadiosityTest, SameSolutionWhateverTheThreadCount) {
    const auto solve = [](int threads) {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                        static_cast<std::size_t>(threads));
        Scene scene = shadowedFloor(2);
        ProgressiveRadiosity solver(scene);
        solver.solve();
        std::vector<Color> values;
        for (const Element& e : solver.mesh().elements)
            values.push_back(e.irradiance[0]);
        return values;
    };
    EXPECT_TRUE(solve(1) == solve(2));
}

// The irradiance the solution gives at every leaf's centroid, both sides, and its statistics.
std::vector<Color> sampleSolution(const ProgressiveRadiosity& solver,
                                  const RadiositySolution& solution) {
    std::vector<Color> values;
    for (const Element& e : solver.mesh().elements) {
        if (!e.isLeaf()) continue;
        for (const Vec3& side : {e.normal, -e.normal})
            values.push_back(solution.irradiance(e.centroid, e.normal, side).value_or(Color(-1)));
    }
    const RadiosityStatistics& s = solution.statistics();
    values.push_back(Color(static_cast<float>(s.shots), static_cast<float>(s.elements),
                           static_cast<float>(s.residualPower)));
    return values;
}

TEST(ProgressiveRadiosityTest, ProgressReportsAndSnapshotsLeaveTheSolutionAsIs) {
    Scene plainScene = furnaceBox(), watchedScene = furnaceBox();
    ProgressiveRadiosity plain(plainScene), watched(watchedScene);
    const RadiositySolution expected = plain.solve();

    std::vector<RadiosityProgress> reports;
    std::vector<std::size_t> snapshotFaces;
    const std::optional<RadiositySolution> solution = watched.solve(
        [&](const RadiosityProgress& progress) {
            reports.push_back(progress);
            snapshotFaces.push_back(watched.snapshot().faceCount());
        },
        nullptr);
    ASSERT_TRUE(solution);
    EXPECT_TRUE(sampleSolution(watched, *solution) == sampleSolution(plain, expected))
        << "the same solution, bit for bit, with or without the reports";

    // Before the first shot, after each one, before each subdivision level, before the gather.
    const std::uint64_t shots = expected.statistics().shots;
    ASSERT_GT(shots, 5u);
    ASSERT_GE(reports.size(), shots + 2);
    for (std::uint64_t k = 0; k <= shots; ++k) {
        EXPECT_EQ(reports[k].phase, RadiosityProgress::Phase::Shooting);
        EXPECT_EQ(reports[k].shots, k);
        EXPECT_EQ(reports[k].unshotPower, plain.unshotHistory()[k]);
        EXPECT_GT(reports[k].initialPower, 0);
    }
    EXPECT_EQ(reports[shots + 1].phase, RadiosityProgress::Phase::Subdividing);
    EXPECT_EQ(reports.back().phase, RadiosityProgress::Phase::Gathering);
    EXPECT_EQ(reports.back().unshotPower, expected.statistics().residualPower);
    for (std::size_t k = 1; k < reports.size(); ++k)
        EXPECT_GE(reports[k].seconds, reports[k - 1].seconds);
    EXPECT_EQ(snapshotFaces.front(), snapshotFaces[shots]) << "shooting does not split elements";
    EXPECT_EQ(snapshotFaces.back(), expected.faceCount()) << "the gather neither";
}

TEST(ProgressiveRadiosityTest, ASnapshotShowsTheLightShotSoFar) {
    Scene scene = furnaceBox();
    ProgressiveRadiosity solver(scene);
    std::vector<float> centre;  // the floor's centre's irradiance, at each shot
    solver.solve(
        [&](const RadiosityProgress& progress) {
            if (progress.phase != RadiosityProgress::Phase::Shooting) return;
            const auto E =
                solver.snapshot().irradiance(Vec3(0.5f, 0, 0.5f), Vec3(0, 1, 0), Vec3(0, 1, 0));
            ASSERT_TRUE(E);
            centre.push_back(E->r);
        },
        nullptr);
    ASSERT_GT(centre.size(), 2u);
    EXPECT_EQ(centre.front(), 0) << "before the first shot, nothing has arrived (no lights)";
    EXPECT_GT(centre.back(), centre[1]) << "the light adds up shot after shot";
    for (std::size_t k = 1; k < centre.size(); ++k)
        EXPECT_GE(centre[k], centre[k - 1]);
}

TEST(ProgressiveRadiosityTest, CancellingStopsBeforeTheNextShot) {
    Scene scene = furnaceBox();
    ProgressiveRadiosity solver(scene);
    std::atomic<bool> cancel{false};
    std::uint64_t lastShots = 0;
    int reports = 0;
    const std::optional<RadiositySolution> solution = solver.solve(
        [&](const RadiosityProgress& progress) {
            ++reports;
            lastShots = progress.shots;
            if (progress.shots == 3) cancel = true;
        },
        &cancel);
    EXPECT_FALSE(solution);
    EXPECT_EQ(lastShots, 3u);
    EXPECT_EQ(reports, 4) << "no shot after the cancel";
}

TEST(ProgressiveRadiosityTest, CancelledBeforeTheStartNothingIsShot) {
    Scene scene = furnaceBox();
    ProgressiveRadiosity solver(scene);
    const std::atomic<bool> cancel{true};
    int reports = 0;
    EXPECT_FALSE(solver.solve([&](const RadiosityProgress&) { ++reports; }, &cancel));
    EXPECT_EQ(reports, 0);
    EXPECT_EQ(solver.unshotHistory().size(), 1u);
}

}  // namespace
}  // namespace lancer::test
