// Alpha cut-outs (a material's "opacity", MTL's map_d): where the mask is below 1/2 the surface is
// not there, for camera rays, shadow rays and every integrator.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "LancerRun.h"

namespace lancer::test {
namespace {

constexpr float kBackground = 0.2f;

// A checker mask of squares 0.5 wide: solid where even, cut away where odd.
const nlohmann::json kCheckerMask = {{"checker", {{"even", 1}, {"odd", 0}, {"scale", 0.5}}}};

nlohmann::json plane(double y, const std::string& material) {
    return {{"type", "plane"}, {"point", {0, y, 0}}, {"normal", {0, 1, 0}}, {"material", material}};
}

const nlohmann::json kSun = {{"type", "directional"}, {"direction", {0, -1, 0}}, {"irradiance", 1}};

class CliCutOut : public testing::TestWithParam<std::string> {};

// Seen from above, a cut-out floor over nothing shows the background exactly through its holes,
// and its surface elsewhere: half the image each, in every integrator.
TEST_P(CliCutOut, CameraRaysPassThroughTheHoles) {
    const nlohmann::json scene = {
        {"render", {{"width", 80}, {"height", 60}, {"spp", 1}, {"integrator", GetParam()}}},
        {"camera", cameraAlongY(0.1, 0.2, 5)},
        {"background", kBackground},
        {"materials", {{"leaf", {{"diffuse", 0.5}, {"opacity", kCheckerMask}}}}},
        {"objects", {plane(0, "leaf")}},
        {"lights", {kSun}}};
    const Image image = renderScene(scene).image;
    int background = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            background += image.at(x, y)[0] == kBackground && image.at(x, y)[1] == kBackground;
    const int pixels = image.width * image.height;
    EXPECT_GT(background, pixels * 0.45) << GetParam();
    EXPECT_LT(background, pixels * 0.55) << GetParam();
}

// A cut-out roof at y = 1 under a sun straight above: the floor below, seen from under the roof,
// is lit exactly where the roof is cut away (half of it) and in shadow elsewhere.
TEST_P(CliCutOut, ShadowRaysPassThroughTheHoles) {
    const nlohmann::json scene = {
        {"render",
         {{"width", 80}, {"height", 60}, {"spp", 4}, {"max_depth", 1}, {"integrator", GetParam()}}},
        {"camera", cameraAlongY(0.1, 0.2, 0.5)},
        {"materials",
         {{"floor", {{"diffuse", 0.8}}}, {"roof", {{"diffuse", 0.5}, {"opacity", kCheckerMask}}}}},
        {"objects", {plane(0, "floor"), plane(1, "roof")}},
        {"lights", {kSun}}};
    const Image image = renderScene(scene).image;
    float brightest = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            brightest = std::max(brightest, image.at(x, y)[0]);
    ASSERT_GT(brightest, 0.1f);
    int lit = 0, dark = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            lit += image.at(x, y)[0] > 0.9f * brightest;
            dark += image.at(x, y)[0] < 0.1f * brightest;
        }
    const int pixels = image.width * image.height;
    EXPECT_GT(lit, pixels * 0.42) << GetParam();
    EXPECT_GT(dark, pixels * 0.42) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Integrators, CliCutOut, testing::Values("whitted", "path"));

// A square of side 2 on y = 0 with uv over [0, 1]^2, without a material library.
const char* const kQuadObj =
    "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 4/4 3/3 2/2 1/1\n";

// The radiosity integrator's camera rays see through the holes too: a square cut by a checker of
// 2 x 2 squares over its uv shows the background over half of it.
TEST(CliCutOut, RadiosityShowsTheBackgroundThroughTheHoles) {
    const TempFolder folder;
    folder.write("quad.obj", kQuadObj);
    const nlohmann::json scene = {
        {"render", {{"width", 40}, {"height", 40}, {"spp", 1}, {"integrator", "radiosity"}}},
        {"camera", cameraAlongY(0, 0, 5)},
        {"background", kBackground},
        {"materials", {{"leaf", {{"diffuse", 0.5}, {"opacity", kCheckerMask}}}}},
        {"objects",
         {{{"type", "mesh"}, {"file", (folder / "quad.obj").string()}, {"material", "leaf"}}}},
        {"lights", {kSun}}};
    const Image image = renderScene(scene).image;
    int background = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            background += image.at(x, y)[0] == kBackground;
    const int pixels = image.width * image.height;
    EXPECT_GT(background, pixels * 0.45);
    EXPECT_LT(background, pixels * 0.55);
}

// MTL's map_d: a quad whose texture's alpha is 0 on its left half and 255 on its right.
TEST(CliCutOut, MtlMapDIsTheTexturesAlpha) {
    const TempFolder folder;
    // A 32-bit uncompressed TGA, 4 x 1, bottom-up, BGRA texels.
    std::string tga(18, '\0');
    tga[2] = 2;
    tga[12] = 4;
    tga[14] = 1;
    tga[16] = 32;
    tga[17] = 8;  // 8 alpha bits
    for (int x = 0; x < 4; ++x)
        tga += std::string("\x80\x80\x80", 3) + (x < 2 ? '\0' : '\xff');
    folder.write("mask.tga", tga);
    folder.write("quad.mtl", "newmtl leaf\nKd 0.5 0.5 0.5\nmap_d mask.tga\n");
    folder.write("quad.obj", std::string("mtllib quad.mtl\nusemtl leaf\n") + kQuadObj);
    const nlohmann::json scene = {
        {"render", {{"width", 40}, {"height", 40}, {"spp", 1}}},
        {"camera", cameraAlongY(0, 0, 5)},
        {"background", kBackground},
        {"objects", {{{"type", "mesh"}, {"file", (folder / "quad.obj").string()}}}},
        {"lights", {kSun}}};
    const Image image = renderScene(scene).image;
    // The quad fills the view; u runs along +x: the left quarter is cut away, the right is there.
    for (int y = 0; y < image.height; ++y) {
        EXPECT_EQ(image.at(4, y)[0], kBackground) << y;
        EXPECT_NE(image.at(35, y)[0], kBackground) << y;
    }
}

}  // namespace
}  // namespace lancer::test
