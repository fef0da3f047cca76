// Clustering in hierarchical radiosity: the cluster tree over the patches, a cluster link's power
// against its children's and against the exact transfer between its members, and the link count
// growing near linearly with the patches where linking every pair grows with their square.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "RadiosityTestSupport.h"
#include "radiosity/FormFactor.h"
#include "radiosity/HierarchicalRadiosity.h"
#include "util/CpuFeatures.h"

namespace lancer::test {
namespace {

const std::string kClustered =
    R"("method": "hierarchical", "threshold": 1e-4, "clusters": true, "subdivision_levels": 0)";

// The closed box [0, 1]^3 with each wall cut into n x n squares, all glowing.
Scene tiledBox(int n) {
    return loadScene(closedBox("glow", n),
                     R"(, "radiosity": {"patch_size": 1, )" + kClustered + "}");
}

// The elements a node stands for: a cluster's members, or the element itself.
std::vector<std::uint32_t> elementsOf(const HierarchicalRadiosity& solver, std::uint32_t node) {
    const ClusterHierarchy& clusters = solver.clusters();
    if (!ClusterHierarchy::isCluster(node)) return {node};
    const auto members = clusters.members(clusters.cluster(node));
    return {members.begin(), members.end()};
}

// The power the receiver's elements take from the source's through the exact point-to-polygon
// form factors from their centroids (each pair by the sides facing each other), unoccluded.
double exactPower(const HierarchicalRadiosity& solver, std::uint32_t receiver,
                  std::uint32_t source) {
    const RadiosityMesh& mesh = solver.mesh();
    double power = 0;
    for (std::uint32_t r : elementsOf(solver, receiver))
        for (std::uint32_t s : elementsOf(solver, source)) {
            const Element& re = mesh.elements[r];
            const Element& se = mesh.elements[s];
            const Vec3 n = dot(re.normal, se.centroid - re.centroid) > 0 ? re.normal : -re.normal;
            const Side side =
                dot(se.normal, re.centroid - se.centroid) > 0 ? Side::Front : Side::Back;
            const double F = FormFactor::pointToSideOfTriangle(Vec3d(re.centroid), Vec3d(n),
                                                               se.corners, se.normal, side);
            power += re.area * F * solver.radiosity()[s][sideIndex(side)].average();
        }
    return power;
}

TEST(HierarchicalClusteringTest, EveryPatchIsInOneClusterTree) {
    Scene scene = tiledBox(2);
    HierarchicalRadiosity solver(scene);
    const ClusterHierarchy& clusters = solver.clusters();
    const std::size_t patches = solver.mesh().patches.size();
    ASSERT_EQ(patches, 48u);
    // A binary tree over the patches: one cluster fewer than its leaves, the top holding all.
    ASSERT_EQ(clusters.clusters().size(), patches - 1);
    EXPECT_EQ(clusters.cluster(clusters.top()).memberCount, patches);
    std::vector<int> seen(patches, 0);
    for (std::uint32_t e : clusters.members(clusters.cluster(clusters.top())))
        ++seen[solver.mesh().elements[e].patch];
    for (int count : seen)
        EXPECT_EQ(count, 1);
    // Each cluster's members are its two children's, and its sphere holds its members' corners.
    for (std::uint32_t c = 0; c < clusters.clusters().size(); ++c) {
        const ClusterHierarchy::Cluster& cluster = clusters.clusters()[c];
        std::uint32_t fromChildren = 0;
        for (std::uint32_t child : cluster.children)
            fromChildren +=
                ClusterHierarchy::isCluster(child) ? clusters.cluster(child).memberCount : 1;
        EXPECT_EQ(fromChildren, cluster.memberCount);
        for (std::uint32_t e : clusters.members(cluster))
            for (const Vec3& corner : solver.mesh().elements[e].corners)
                EXPECT_LE(length(corner - cluster.center), cluster.radius * 1.0001f);
    }
}

TEST(HierarchicalClusteringTest, TheClustersHoldingARootAreItsAncestors) {
    Scene scene = tiledBox(2);
    HierarchicalRadiosity solver(scene);
    const ClusterHierarchy& clusters = solver.clusters();
    const std::uint32_t root = clusters.members(clusters.cluster(clusters.top()))[5];
    const std::vector<char> holding =
        clusters.clustersHolding([&](std::uint32_t e) { return e == root; });
    ASSERT_EQ(holding.size(), clusters.clusters().size());
    std::vector<char> ancestors(clusters.clusters().size(), 0);
    for (std::uint32_t k = clusters.parentOf(root); k != Element::kNone;
         k = clusters.clusters()[k].parent)
        ancestors[k] = 1;
    EXPECT_EQ(holding, ancestors);
    EXPECT_GT(std::count(holding.begin(), holding.end(), 1), 2);
    // None holds what no root is.
    for (char h : clusters.clustersHolding([](std::uint32_t) { return false; }))
        EXPECT_EQ(h, 0);
}

TEST(HierarchicalClusteringTest, AClusterLinksPowerIsItsChildrensAndItsMembers) {
    // A glowing ceiling of 8 x 8 squares over a floor of 8 x 8: far enough apart, pieces of each
    // are linked as clusters.
    Scene scene =
        loadScene(tiledSquare(Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0), 8, "white") + ", " +
                      tiledSquare(Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, 1), 8, "glow"),
                  R"(, "radiosity": {"patch_size": 1, )" + kClustered + "}");
    HierarchicalRadiosity solver(scene);
    ASSERT_TRUE(solver.solve({}, nullptr));
    const ClusterHierarchy& clusters = solver.clusters();
    int checked = 0;
    for (const HierarchicalRadiosity::ClusterLink& link : solver.clusterLinks()) {
        if (!ClusterHierarchy::isCluster(link.source)) continue;
        const double power = solver.clusterLinkPower(link).average();
        ASSERT_GT(power, 0);
        // Nothing is in the way: all the link's rays got through.
        EXPECT_FALSE(link.partlyVisible());
        // The same receiver linked to each of the source's two children instead.
        double children = 0;
        for (std::uint32_t child : clusters.cluster(link.source).children) {
            HierarchicalRadiosity::ClusterLink part = link;
            part.source = child;
            children += solver.clusterLinkPower(part).average();
        }
        // Both within the oracle's bound on the link's relative error.
        const float spread = solver.clusterSpread(link.receiver, link.source);
        EXPECT_NEAR(power, children, spread * power) << link.receiver << " " << link.source;
        EXPECT_NEAR(power, exactPower(solver, link.receiver, link.source), spread * power)
            << link.receiver << " " << link.source;
        ++checked;
    }
    EXPECT_GT(checked, 10);
}

TEST(HierarchicalClusteringTest, TheLinkCountGrowsNearLinearly) {
    // Boxes of 192, 768 and 3072 patches: linking every pair of patches first would make 16 times
    // the links for 4 times the patches. (The smaller boxes' links are mostly between
    // neighbouring patches, too near each other to be clustered.)
    std::vector<double> links;
    for (int n : {4, 8, 16}) {
        Scene scene = tiledBox(n);
        HierarchicalRadiosity solver(scene);
        ASSERT_TRUE(solver.solve({}, nullptr));
        const auto patches = static_cast<double>(solver.mesh().patches.size());
        links.push_back(static_cast<double>(solver.linkCount()));
        std::cout << patches << " patches: " << links.back() << " links, "
                  << solver.clusterLinks().size() << " with a cluster\n";
        EXPECT_GT(solver.clusterLinks().size(), 0u);
        if (n == 16) {
            EXPECT_LT(links.back(), patches * patches / 8);
        }
    }
    // Measured: 29,555, 134,729 and 376,097 links.
    EXPECT_LT(links[2], 1.5 * 4 * links[1]);
}

TEST(HierarchicalClusteringTest, DimClustersNearEachOtherAreLinkedAsClusters) {
    // A torus of 2,160 small patches lit from above: its inner side sees much of itself from
    // near by (as a scanned model or a knot does), through clusters closer to each other than
    // three times their radii, each bringing little. Such a pair is linked as clusters where its
    // light, counted with a relative error of kNearSpread (24), is below the threshold; with 64 it
    // hardly ever was, and every such pair was refined into links between elements. Measured:
    // 162,922 links (241,786 with 64; the 10k-triangle knot of bench/radiosity_scaling.py 14.9
    // million -> 12.2 million, the 200k knot 58.7 million -> 32.2 million).
    Scene scene = loadScene(
        R"({"type": "torus", "major_radius": 0.25, "minor_radius": 0.1, "material": "white"})",
        R"(, "lights": [{"type": "quad", "corner": [-0.5, 1, -0.5], "edge1": [1, 0, 0],
                         "edge2": [0, 0, 1], "radiance": 1}],
             "radiosity": {"method": "hierarchical", "clusters": true, "patch_size": 0.08,
                           "subdivision_levels": 0})");
    HierarchicalRadiosity solver(scene);
    ASSERT_TRUE(solver.solve({}, nullptr));
    EXPECT_EQ(solver.mesh().patches.size(), 2160u);
    EXPECT_LT(solver.linkCount(), 200000u);
    EXPECT_GT(solver.clusterLinks().size(), 0u);
}

TEST(HierarchicalClusteringTest, TheAvx2SumsGiveTheBaselinesBits) {
    // The cluster sums (a cluster's members at a point, the cluster links a leaf takes) run in
    // AVX2 where the CPU has it: the solution must be the baseline's to the bit.
    if (!CpuFeatures::avx2()) GTEST_SKIP() << "no AVX2 on this CPU: only the baseline runs";
    Scene scene = tiledBox(8);
    std::array<std::vector<std::array<Color, 2>>, 2> solutions;
    for (const bool baseline : {false, true}) {
        CpuFeatures::useBaselineOnly(baseline);
        HierarchicalRadiosity solver(scene);
        const bool solved = solver.solve({}, nullptr).has_value();
        CpuFeatures::useBaselineOnly(false);
        ASSERT_TRUE(solved);
        ASSERT_GT(solver.clusterLinks().size(), 0u);
        solutions[baseline] = solver.radiosity();
    }
    ASSERT_EQ(solutions[0].size(), solutions[1].size());
    EXPECT_EQ(std::memcmp(solutions[0].data(), solutions[1].data(),
                          solutions[0].size() * sizeof(solutions[0][0])),
              0);
}

}  // namespace
}  // namespace lancer::test
