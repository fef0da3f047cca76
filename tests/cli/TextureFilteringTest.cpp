// Texture filtering seen through the camera: the pixel's footprint on a textured floor picks the
// mip level, so far away the texture averages out instead of aliasing, while near the camera its
// detail stays sharp.

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "LancerRun.h"

namespace lancer::test {
namespace {

// A 64 x 64 greyscale image (ASCII PGM) of black and white squares 8 texels wide: its mean in
// linear radiance is 0.5 (sRGB 0 and 255 decode to 0 and 1).
std::string checkerImage() {
    std::ostringstream pgm;
    pgm << "P2\n64 64\n255\n";
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            pgm << (((x / 8 + y / 8) % 2) ? 255 : 0) << (x == 63 ? '\n' : ' ');
    return pgm.str();
}

TEST(CliTextureFiltering, FarFloorAveragesNearFloorStaysSharp) {
    const TempFolder folder;
    folder.write("checker.pgm", checkerImage());
    // The floor's uv are its world (x, z): the image repeats every unit. Lit from straight above
    // with irradiance 1 and no ambient, a pixel's radiance is the texture's value there.
    folder.write("scene.json", R"({
      "render": { "width": 160, "height": 120, "spp": 1, "max_depth": 0 },
      "camera": { "position": [0, 1, 0], "look_at": [0, 0.5, -10], "vfov": 40 },
      "materials": { "floor": { "diffuse": { "texture": "checker.pgm" } } },
      "objects": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" } ],
      "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": 1 } ]
    })");
    const RunResult run = runLancer({"scene.json", "-o", "out.pfm", "--quiet"}, folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    const Image image = loadImage(folder / "out.pfm");

    // The horizon is at row 51.8; rows 53 to 62 see the floor more than 15 units away, where a
    // pixel covers dozens of texels along the view: only the image's mean may show. Point
    // sampling would give values anywhere in [0, 1] here.
    for (int y = 53; y <= 62; ++y)
        for (int x = 0; x < image.width; ++x)
            EXPECT_NEAR(image.at(x, y)[0], 0.5, 0.02) << "pixel " << x << ", " << y;

    // The bottom rows see the floor 2 to 3 units away, where a pixel covers about two texels of
    // squares eight texels wide: the squares must still be black and white, not grey.
    float darkest = 1, brightest = 0;
    for (int y = 100; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            darkest = std::min(darkest, image.at(x, y)[0]);
            brightest = std::max(brightest, image.at(x, y)[0]);
        }
    EXPECT_LT(darkest, 0.1f);
    EXPECT_GT(brightest, 0.9f);
}

}  // namespace
}  // namespace lancer::test
