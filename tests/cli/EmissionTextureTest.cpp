// Textured emission ("emission": a texture): the camera sees it texel by texel, and a textured
// emitter lights the scene as the same emitter cut into uniform pieces does, in every integrator
// (lights sample the radiance at their points, radiosity patches average it).

#include <gtest/gtest.h>

#include <string>

#include "LancerRun.h"

namespace lancer::test {
namespace {

// A checker of 2 x 2 squares over the uv square: radiance 2 on the even squares, 0 on the odd.
const nlohmann::json kCheckerEmission = {{"checker", {{"even", 2}, {"odd", 0}, {"scale", 0.5}}}};

// A square of side 2 on y = 0 facing down, with uv over [0, 1]^2, whose four quarters (u and v
// below or above 1/2) can also be written as faces of their own.
const char* const kVertices =
    "v -1 0 -1\nv 0 0 -1\nv 1 0 -1\nv -1 0 0\nv 0 0 0\nv 1 0 0\nv -1 0 1\nv 0 0 1\nv 1 0 1\n"
    "vt 0 0\nvt 0.5 0\nvt 1 0\nvt 0 0.5\nvt 0.5 0.5\nvt 1 0.5\nvt 0 1\nvt 0.5 1\nvt 1 1\n";
// Quarter (i, j) of the square, i along u (x), j along v (z), facing -y.
std::string quarter(int i, int j) {
    const int a = 1 + i + 3 * j, b = a + 1, c = a + 4, d = a + 3;
    const auto corner = [](int k) { return std::to_string(k) + "/" + std::to_string(k); };
    return "f " + corner(a) + " " + corner(b) + " " + corner(c) + " " + corner(d) + "\n";
}

// The camera looks up at the textured square from below: every pixel is one of its radiances.
TEST(CliEmissionTexture, CameraSeesTheRadianceOfEachTexel) {
    const TempFolder folder;
    folder.write("square.obj", std::string(kVertices) + quarter(0, 0) + quarter(1, 0) +
                                   quarter(0, 1) + quarter(1, 1));
    for (const char* integrator : {"whitted", "path"}) {
        const nlohmann::json scene = {
            {"render", {{"width", 40}, {"height", 40}, {"spp", 1}, {"integrator", integrator}}},
            {"camera", cameraAlongY(0, 0, -5)},
            {"materials", {{"lamp", {{"diffuse", 0}, {"emission", kCheckerEmission}}}}},
            {"objects",
             {{{"type", "mesh"},
               {"file", (folder / "square.obj").string()},
               {"material", "lamp"}}}}};
        const Image image = renderScene(scene).image;
        int bright = 0, dark = 0;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                bright += image.at(x, y)[0] == 2.0f;
                dark += image.at(x, y)[0] == 0.0f;
            }
        const int pixels = image.width * image.height;
        EXPECT_GT(bright, pixels * 0.45) << integrator;
        EXPECT_GT(dark, pixels * 0.45) << integrator;
    }
}

// A floor (a box: radiosity meshes an infinite plane only inside the bounded shapes' box) lit only
// by the square 0.5 above it (in the integrators where emitters light the scene:
// Whitted lights by the scene's lights only), with the checker texture, and with the square's
// two even quarters as uniform emitters of radiance 2 (the odd ones black). The near field tells
// the two apart from a uniform emitter of the mean radiance: under a bright quarter the floor is
// much brighter than under a dark one.
TEST(CliEmissionTexture, LightsTheSceneAsItsPiecesDo) {
    const TempFolder folder;
    folder.write("square.obj", std::string(kVertices) + quarter(0, 0) + quarter(1, 0) +
                                   quarter(0, 1) + quarter(1, 1));
    folder.write("pieces.mtl",
                 "newmtl bright\nKd 0 0 0\nKe 2 2 2\nillum 1\nnewmtl dark\nKd 0 0 0\nillum 1\n");
    folder.write("pieces.obj", std::string("mtllib pieces.mtl\n") + kVertices + "usemtl bright\n" +
                                   quarter(0, 0) + quarter(1, 1) + "usemtl dark\n" + quarter(1, 0) +
                                   quarter(0, 1));
    const auto floorUnder = [&](const nlohmann::json& emitter, const std::string& integrator) {
        nlohmann::json scene = {
            {"render", {{"width", 16}, {"height", 16}, {"spp", 256}, {"integrator", integrator}}},
            {"camera", cameraAlongY(0, 0, 0.25)},
            {"materials",
             {{"floor", {{"diffuse", 0.5}}},
              {"lamp", {{"diffuse", 0}, {"emission", kCheckerEmission}}}}},
            {"objects",
             {{{"type", "box"},
               {"min", {-1.5, -0.1, -1.5}},
               {"max", {1.5, 0, 1.5}},
               {"material", "floor"}},
              emitter}}};
        if (integrator == "radiosity")
            scene["radiosity"] = {{"patch_size", 0.5}, {"subdivision_levels", 0}};
        return renderScene(scene).image;
    };
    const nlohmann::json textured = {{"type", "mesh"},
                                     {"file", (folder / "square.obj").string()},
                                     {"material", "lamp"},
                                     {"transform", {{"translate", {0, 0.5, 0}}}}};
    const nlohmann::json pieces = {{"type", "mesh"},
                                   {"file", (folder / "pieces.obj").string()},
                                   {"transform", {{"translate", {0, 0.5, 0}}}}};
    for (const char* integrator : {"path", "radiosity"}) {
        const Image fromTexture = floorUnder(textured, integrator);
        const Image fromPieces = floorUnder(pieces, integrator);
        // The floor under the bright quarter (u, v < 1/2: x, z < 0, the image's top left) and
        // under the dark one beside it.
        const auto meanOver = [](const Image& image, int x0, int y0) {
            double sum = 0;
            for (int y = y0; y < y0 + 4; ++y)
                for (int x = x0; x < x0 + 4; ++x)
                    sum += image.at(x, y)[0];
            return sum / 16;
        };
        const double bright = meanOver(fromPieces, 2, 2), dark = meanOver(fromPieces, 10, 2);
        ASSERT_GT(bright, 2 * dark) << integrator;
        EXPECT_NEAR(meanOver(fromTexture, 2, 2), bright, 0.03 * bright) << integrator;
        EXPECT_NEAR(meanOver(fromTexture, 10, 2), dark, 0.03 * bright) << integrator;
        EXPECT_NEAR(meanValue(fromTexture), meanValue(fromPieces), 0.02 * meanValue(fromPieces))
            << integrator;
    }
}

}  // namespace
}  // namespace lancer::test
