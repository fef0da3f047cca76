// PLY models end to end: the unit cube of tests/mesh/data/ply as OBJ and as PLY (ASCII, binary
// little and big endian) renders the same image, placed by a transform: with a checker in its uvs
// and its normals, with the default grey without "material", and flat or "smooth" without normals.

#include <gtest/gtest.h>

#include "LancerRun.h"

namespace lancer::test {
namespace {

using json = nlohmann::json;

const fs::path kCubes = fs::path(LANCER_SOURCE_DIR) / "tests/mesh/data/ply";

// The cube, turned to show three faces, under a point light; `extra` is added to its object.
json cubeScene(const std::string& file, const json& extra) {
    json cube = {{"type", "mesh"},
                 {"file", (kCubes / file).string()},
                 {"transform", {{"translate", {-0.5, -0.5, -0.5}}, {"rotate", {1, 1, 0, 35}}}}};
    cube.update(extra);
    return {{"render", {{"width", 40}, {"height", 32}, {"spp", 2}, {"max_depth", 2}}},
            {"camera", {{"position", {1.5, 1.2, 2.5}}, {"look_at", {0, 0, 0}}}},
            {"materials",
             {{"checker",
               {{"diffuse", {{"checker", {{"even", 0.9}, {"odd", 0.2}, {"scale", 0.5}}}}},
                {"specular", 0.3}}}}},
            {"objects", {cube}},
            {"lights", {{{"type", "point"}, {"position", {3, 4, 5}}, {"intensity", 40}}}}};
}

// The same triangles up to the diagonal each quad is split along, which moves a hit by rounding.
constexpr double kSameImage = 1e-5;

TEST(CliPly, PlyRendersAsTheObjOfTheSameCube) {
    // The model's normals and uvs (a checker), and the default grey without "material".
    for (const json& extra : {json{{"material", "checker"}}, json::object()}) {
        const Image obj = renderScene(cubeScene("cube.obj", extra)).image;
        EXPECT_GT(meanValue(obj), 0.01) << extra;
        for (const char* file : {"cube-ascii.ply", "cube-binary-le.ply", "cube-binary-be.ply"}) {
            const Image ply = renderScene(cubeScene(file, extra)).image;
            EXPECT_LE(maxAbsoluteDifference(ply, obj), kSameImage) << file << " " << extra;
        }
    }
}

TEST(CliPly, SmoothAppliesToPlyAsToObj) {
    const json smooth = {{"smooth", 100}};
    const Image flat = renderScene(cubeScene("cube-positions.ply", json::object())).image;
    EXPECT_LE(maxAbsoluteDifference(
                  flat, renderScene(cubeScene("cube-positions.obj", json::object())).image),
              kSameImage);
    const Image smoothed = renderScene(cubeScene("cube-positions.ply", smooth)).image;
    EXPECT_LE(
        maxAbsoluteDifference(smoothed, renderScene(cubeScene("cube-positions.obj", smooth)).image),
        kSameImage);
    EXPECT_GT(maxAbsoluteDifference(smoothed, flat), 0.05);
}

}  // namespace
}  // namespace lancer::test
