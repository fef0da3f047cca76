// The camera types end to end: what an orthographic, a lat-long and a fisheye render show of
// self-lit objects, where each is seen exactly as its emission (whitted, max_depth 0, no lights).

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "LancerRun.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

// A scene of self-lit objects on a black background: a pixel is the emission of what it sees
// (times the part of the pixel that sees it), whatever the camera.
json selfLitScene(const json& camera, int width, int height, const json& objects) {
    return {{"render",
             {{"width", width},
              {"height", height},
              {"spp", 16},
              {"max_depth", 0},
              {"integrator", "whitted"}}},
            {"camera", camera},
            {"objects", objects}};
}

json withGlowMaterials(json scene, const std::vector<std::pair<std::string, json>>& colours) {
    for (const auto& [name, colour] : colours)
        scene["materials"][name] = {{"diffuse", 0}, {"specular", 0}, {"emission", colour}};
    return scene;
}

// Three spheres of radius 0.5 at depths 0, 5 and 10 ahead of an orthographic camera whose view
// is 4 units high in 32 pixels: each covers pi r^2 / (4/32)^2 = 50.27 pixels, at every depth (a
// perspective camera would make them shrink with distance).
TEST(CliCameraTypes, OrthographicSpheresAtDifferentDepthsShowEqualDiscs) {
    const json camera = {
        {"type", "orthographic"}, {"position", {0, 0, 10}}, {"look_at", {0, 0, 0}}, {"height", 4}};
    json objects = json::array();
    for (int i = 0; i < 3; ++i)
        objects.push_back({{"type", "sphere"},
                           {"center", {-4 + 4 * i, 0, -5 * i}},
                           {"radius", 0.5},
                           {"material", "white"}});
    const json scene = withGlowMaterials(selfLitScene(camera, 96, 32, objects), {{"white", 1}});
    const Image image = renderScene(scene).image;
    const double expected = kPi * 0.25 / (0.125 * 0.125);
    for (int i = 0; i < 3; ++i) {
        double covered = 0;  // pixels, fractions at the rim
        for (int y = 0; y < 32; ++y)
            for (int x = 32 * i; x < 32 * (i + 1); ++x)
                covered += image.at(x, y)[0];
        // 16 stratified samples per pixel: each of the ~25 rim pixels is off by up to 1/16 at
        // worst, about +-0.1 in total by the central limit; 2% (1 pixel) leaves room for that.
        EXPECT_NEAR(covered, expected, 0.02 * expected) << "sphere " << i;
    }
    // The middle sphere is centred on the view: its centre pixel is fully covered.
    EXPECT_FLOAT_EQ(image.at(48, 16)[0], 1);
}

// Six spheres of different colours at distance 5 along +-x, +-y, +-z around a lat-long camera
// at the origin looking along -z with y up: each is where u = 0.5 + atan2(d.x, -d.z) / (2 pi),
// v = acos(d.y) / pi puts its centre (it covers asin(1/5) = 11.5 degrees around it, two pixels of
// the 64 x 32 image's 5.6-degree rows).
TEST(CliCameraTypes, LatLongShowsTheSixAxesWhereTheEnvironmentMappingPutsThem) {
    const json camera = {{"type", "latlong"}, {"position", {0, 0, 0}}, {"look_at", {0, 0, -1}}};
    const std::vector<std::pair<std::string, json>> colours = {
        {"px", {1, 0, 0}}, {"nx", {0, 1, 0}}, {"py", {0, 0, 1}},
        {"ny", {1, 1, 0}}, {"pz", {0, 1, 1}}, {"nz", {1, 0, 1}}};
    const std::vector<std::array<int, 3>> centres = {{5, 0, 0},  {-5, 0, 0}, {0, 5, 0},
                                                     {0, -5, 0}, {0, 0, 5},  {0, 0, -5}};
    json objects = json::array();
    for (std::size_t i = 0; i < centres.size(); ++i)
        objects.push_back({{"type", "sphere"},
                           {"center", {centres[i][0], centres[i][1], centres[i][2]}},
                           {"radius", 1},
                           {"material", colours[i].first}});
    const Image image =
        renderScene(withGlowMaterials(selfLitScene(camera, 64, 32, objects), colours)).image;
    const auto expectColour = [&](int x, int y, const json& colour, const std::string& what) {
        for (int c = 0; c < 3; ++c)
            EXPECT_FLOAT_EQ(image.at(x, y)[static_cast<std::size_t>(c)], colour[c].get<float>())
                << what << " at pixel " << x << ", " << y;
    };
    // The pixels whose whole area is within the sphere seen along each axis:
    // +x: u = 3/4; -x: u = 1/4; -z: u = 1/2; +z: u = 0 = 1 (both edges); +y: v = 0; -y: v = 1.
    for (const int y : {15, 16}) {
        expectColour(48, y, colours[0].second, "+x");
        expectColour(15, y, colours[1].second, "-x");
        expectColour(32, y, colours[5].second, "-z");
        expectColour(0, y, colours[4].second, "+z");
        expectColour(63, y, colours[4].second, "+z");
    }
    for (int x = 0; x < 64; x += 7) {
        expectColour(x, 0, colours[2].second, "+y");
        expectColour(x, 31, colours[3].second, "-y");
    }
    // Between them, at 45 degrees, nothing.
    expectColour(40, 16, {0, 0, 0}, "between -z and +x");
}

// A fisheye of 180 degrees looking along -z with a glowing floor y = -1 below it and a glowing
// wall z = 1 behind it, on a blue background: the lower half of the image circle sees the floor,
// the upper half the sky (the horizon is its diameter), the wall behind is never seen, and the
// corners outside the circle are black. At 360 degrees the wall shows in the outer ring.
TEST(CliCameraTypes, FisheyeOf180DegreesSeesAHemisphere) {
    const json objects = {
        {{"type", "plane"}, {"point", {0, -1, 0}}, {"normal", {0, 1, 0}}, {"material", "floor"}},
        {{"type", "plane"}, {"point", {0, 0, 1}}, {"normal", {0, 0, -1}}, {"material", "wall"}}};
    json camera = {
        {"type", "fisheye"}, {"position", {0, 0, 0}}, {"look_at", {0, 0, -1}}, {"fov", 180}};
    json scene = withGlowMaterials(selfLitScene(camera, 64, 64, objects),
                                   {{"floor", {0, 1, 0}}, {"wall", {1, 0, 0}}});
    scene["background"] = {0, 0, 0.5};
    const Image image = renderScene(scene).image;
    int floor = 0, sky = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const Image::Rgb& p = image.at(x, y);
            EXPECT_EQ(p[0], 0) << "the wall behind is seen at pixel " << x << ", " << y;
            // The pixel's farthest and nearest points from the centre, in units of the radius.
            const double dx = std::abs(x + 0.5 - 32), dy = std::abs(y + 0.5 - 32);
            const double nearest = std::hypot(std::max(dx - 0.5, 0.0), std::max(dy - 0.5, 0.0));
            const double farthest = std::hypot(dx + 0.5, dy + 0.5);
            if (nearest >= 32) {
                EXPECT_EQ(p[1] + p[2], 0) << "outside the circle at pixel " << x << ", " << y;
            } else if (farthest <= 32 && y >= 32) {
                EXPECT_EQ(p[1], 1) << "below the horizon at pixel " << x << ", " << y;
                ++floor;
            } else if (farthest <= 32 && y < 32) {
                EXPECT_EQ(p[2], 0.5f) << "above the horizon at pixel " << x << ", " << y;
                ++sky;
            }
        }
    }
    EXPECT_GT(floor, 1400);  // of about pi 32^2 / 2 = 1608
    EXPECT_EQ(floor, sky);

    scene["camera"]["fov"] = 360;
    const Image all = renderScene(scene).image;
    // Three quarters of the radius up: 135 degrees from the view, up and back: the wall.
    EXPECT_EQ(all.at(32, 8)[0], 1);
    // A little less than half way up: 82 degrees from the view, up and ahead: the sky.
    EXPECT_EQ(all.at(31, 17)[2], 0.5f);
}

// Perspective is the default type: naming it changes no byte.
TEST(CliCameraTypes, PerspectiveIsTheDefault) {
    json scene = selfLitScene(
        {{"position", {0, 0, 3}}, {"look_at", {0, 0, 0}}, {"vfov", 30}}, 24, 16,
        {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 0.5}, {"material", "white"}}});
    scene = withGlowMaterials(scene, {{"white", 1}});
    const std::string unnamed = renderScene(scene).bytes;
    scene["camera"]["type"] = "perspective";
    EXPECT_EQ(renderScene(scene).bytes, unnamed);
}

}  // namespace
}  // namespace lancer::test
