// The thin-lens camera end to end: aperture 0 is the pinhole camera bit for bit, and with an
// aperture the focal plane stays sharp while what lies off it is blurred.

#include <gtest/gtest.h>

#include <cmath>

#include "ClosedForm.h"

namespace lancer::test {
namespace {

using nlohmann::json;

TEST(CliThinLens, ApertureZeroIsThePinholeCameraBitForBit) {
    json scene = loadWhittedScene();
    scene["render"]["width"] = 64;
    scene["render"]["height"] = 48;
    scene["render"]["spp"] = 4;
    scene["camera"].erase("aperture");
    scene["camera"].erase("focus_distance");
    const std::string pinhole = renderScene(scene).bytes;
    scene["camera"]["aperture"] = 0;
    EXPECT_EQ(renderScene(scene).bytes, pinhole);
    scene["camera"]["focus_distance"] = 1.5;
    EXPECT_EQ(renderScene(scene).bytes, pinhole) << "focus_distance alone changes nothing";
}

// Looking down -z from z = 5, focused at z = 0: on the left a checkered rectangle in the focal
// plane (x in [-3, 0]), on the right a checkered plane at z = -5, far out of focus. Each is lit
// head-on by a directional light, so that a pixel is the checker's kd where it sees one square.
const CameraModel kCamera{.position = {0, 0, 5}, .lookAt = {0, 0, 0}, .width = 64, .height = 48};

json focusScene(double aperture) {
    json scene = json::parse(R"({
      "render": { "spp": 16, "max_depth": 0 },
      "background": 0, "ambient": 0,
      "materials": {
        "near": { "diffuse": { "checker": { "even": 0.9, "odd": 0.1, "scale": 0.25 } } },
        "far":  { "diffuse": { "checker": { "even": 0.9, "odd": 0.1, "scale": 0.5 } } }
      },
      "objects": [
        { "type": "triangle", "vertices": [[-3, -3, 0], [0, -3, 0], [0, 3, 0]],
          "uvs": [[-3, -3], [0, -3], [0, 3]], "material": "near" },
        { "type": "triangle", "vertices": [[-3, -3, 0], [0, 3, 0], [-3, 3, 0]],
          "uvs": [[-3, -3], [0, 3], [-3, 3]], "material": "near" },
        { "type": "plane", "point": [0, 0, -5], "normal": [0, 0, 1], "material": "far" }
      ],
      "lights": [ { "type": "directional", "direction": [0, 0, -1], "irradiance": 1 } ]
    })");
    kCamera.placeIn(scene);
    scene["render"]["spp"] = 16;
    scene["camera"]["aperture"] = aperture;
    scene["camera"]["focus_distance"] = 5;
    return scene;
}

// Where a pixel's centre ray meets the plane z = 0.
double focalPlaneX(int i, int j) {
    const RayD ray = kCamera.rayThroughPixelCentre(i, j);
    return ray.at(intersectPlane(ray, {0, 0, 0}, {0, 0, 1}).value()).x;
}

// The standard deviation of the red channel over the pixels that `inRegion` selects.
template <typename Region>
double contrast(const Image& image, const Region& inRegion) {
    double sum = 0, sumSquares = 0;
    int count = 0;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            if (!inRegion(i, j)) continue;
            const double v = image.at(i, j)[0];
            sum += v;
            sumSquares += v * v;
            ++count;
        }
    const double mean = sum / count;
    return std::sqrt(std::max(0.0, sumSquares / count - mean * mean));
}

TEST(CliThinLens, TheFocalPlaneStaysSharpWhileWhatLiesBehindItBlurs) {
    const Image pinhole = renderScene(focusScene(0)).image;
    const Image lens = renderScene(focusScene(0.3)).image;
    // A pixel is wholly on the rectangle when its centre is more than a pixel width (0.076 at
    // z = 0) inside the rectangle's edge x = 0; wholly on the far plane when its centre is
    // beyond the blur of the rectangle's edge there (the lens radius, scaled to z = 0 ... 0.3).
    const auto onFocalPlane = [](int i, int j) { return focalPlaneX(i, j) < -0.1; };
    const auto offFocalPlane = [](int i, int j) { return focalPlaneX(i, j) > 0.35; };

    // In focus, every lens ray through a sample point meets the same point of the focal plane as
    // the pinhole ray: the same squares, the same values, but for samples within rounding of a
    // square's edge.
    int focalPixels = 0, samePixels = 0;
    for (int j = 0; j < kCamera.height; ++j)
        for (int i = 0; i < kCamera.width; ++i) {
            if (!onFocalPlane(i, j)) continue;
            ++focalPixels;
            samePixels += std::abs(lens.at(i, j)[0] - pinhole.at(i, j)[0]) <= 1e-5f;
        }
    EXPECT_GT(focalPixels, 1000);
    EXPECT_GE(samePixels, focalPixels - 2) << "of " << focalPixels << " pixels in focus";
    const double sharpContrast = contrast(pinhole, onFocalPlane);
    EXPECT_GT(sharpContrast, 0.3) << "the squares are resolved";
    EXPECT_NEAR(contrast(lens, onFocalPlane), sharpContrast, 1e-3 * sharpContrast);

    // Behind the focal plane the blur disc (0.3 at z = -5, wider than a square of 0.5... 0.6
    // across) averages the squares towards their mean.
    const double pinholeFar = contrast(pinhole, offFocalPlane);
    EXPECT_GT(pinholeFar, 0.3) << "the far squares are resolved by the pinhole camera";
    EXPECT_LT(contrast(lens, offFocalPlane), 0.5 * pinholeFar) << "and blurred by the lens";
}

}  // namespace
}  // namespace lancer::test
