// Area lights end to end, on linear .pfm output: the irradiance under a quad light matches
// Lambert's closed form for a polygon, a blocker casts a penumbra whose every pixel matches the
// closed form for the part of the light it still sees, quad and sphere lights are seen as their
// radiance (a quad only from the front), and a spot light lights its cone only.
//
// The floor is Lambertian with kd = 0.5 and the renders use max_depth 0, so a floor pixel is
// kd E_l (the contract's shading with n.L folded into the average over the light's samples). With
// one sample per pixel that sample is the pixel centre, so each pixel is compared with the closed
// form at the floor point its centre ray meets. 4096 stratified samples per light leave an
// error far below the 1% tolerance; pixels that see the edge of the shadow carry the noise of
// the visibility step across one row of strata (about 1e-3 of the full value), hence a small
// absolute tolerance there.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ClosedForm.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr double kKd = 0.5;
constexpr double kRadiance = 4;
constexpr double kRelativeTolerance = 0.01;
const Vec3d kUp{0, 1, 0};

// A 1 x 1 quad light at height 2 over the origin, facing down.
const json kQuadLight = json::parse(R"({ "type": "quad", "corner": [-0.5, 2, -0.5],
    "edge1": [1, 0, 0], "edge2": [0, 0, 1], "radiance": 4, "samples": 4096 })");

// A camera just under the height of the blocker, looking straight down at the floor y = 0, image
// x along world x: 45 pixels over x in [-0.9, 0.9], 5 rows around z = 0.
const CameraModel kFloorCamera{.position = {0, 0.9, 0},
                               .lookAt = {0, 0, 0},
                               .up = {0, 0, -1},
                               .vfovDegrees = 2 * std::atan(1.0 / 9) * 180 / 3.14159265358979323846,
                               .width = 45,
                               .height = 5};

json floorScene(const json& lights, const json& extraObjects = json::array()) {
    json scene = json::parse(R"({
      "background": 0, "ambient": 0,
      "materials": { "floor": { "diffuse": 0.5 } },
      "objects": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                     "material": "floor" } ]
    })");
    for (const json& object : extraObjects)
        scene["objects"].push_back(object);
    scene["lights"] = lights;
    kFloorCamera.placeIn(scene);
    scene["render"]["max_depth"] = 0;
    return scene;
}

Vec3d floorPoint(const RayD& ray) {
    return ray.at(intersectPlane(ray, Vec3d(0, 0, 0), kUp).value());
}

// The part x >= xMin of the light, as seen from the floor: a polygon of radiance kRadiance.
double lightVisibleBeyond(const Vec3d& p, double xMin) {
    const double x0 = std::clamp(xMin, -0.5, 0.5);
    if (x0 >= 0.5) return 0;
    return kRadiance *
           polygonIrradiance(p, kUp, {{x0, 2, -0.5}, {0.5, 2, -0.5}, {0.5, 2, 0.5}, {x0, 2, 0.5}});
}

TEST(CliAreaLight, IrradianceUnderAQuadLightMatchesTheClosedFormWithinOnePercent) {
    const Image image = renderScene(floorScene(json::array({kQuadLight}))).image;
    const int checked = expectPixelsMatch(
        image, kFloorCamera,
        [](const RayD& ray) -> std::optional<Radiance> {
            const double E = lightVisibleBeyond(floorPoint(ray), -0.5);
            return Radiance{E, E, E} * Radiance{kKd, kKd, kKd};
        },
        kRelativeTolerance, 0);
    EXPECT_EQ(checked, kFloorCamera.width * kFloorCamera.height);
}

TEST(CliAreaLight, ManyPixelSamplesWithFewLightSamplesEachConvergeToo) {
    // 256 pixel samples times 16 light samples (the default): each pixel sample gets its own
    // offset of the light's strata. Pixels are averages over their area, so only the middle of
    // the image, where the irradiance is nearly flat, is compared with the value at the centre.
    json light = kQuadLight;
    light.erase("samples");
    json scene = floorScene(json::array({light}));
    scene["render"]["spp"] = 256;
    const Image image = renderScene(scene).image;
    for (int i = 20; i <= 24; ++i) {
        const double expected =
            kKd * lightVisibleBeyond(floorPoint(kFloorCamera.rayThroughPixelCentre(i, 2)), -0.5);
        EXPECT_NEAR(image.at(i, 2)[0], expected, kRelativeTolerance * expected) << "pixel " << i;
    }
}

// An opaque half-plane at height 1 over x < 0 (half-way up to the light): from the floor point
// (x, 0, z) it hides the light points with x_light < -x, so x <= -0.5 is the umbra, x >= 0.5 is
// fully lit and the penumbra lies between.
const json kBlocker = json::parse(R"({ "type": "triangle",
    "vertices": [[0, 1, -10], [0, 1, 10], [-20, 1, 0]] })");

TEST(CliAreaLight, ABlockerCastsAPenumbraThatMatchesTheVisiblePartOfTheLight) {
    const Image image =
        renderScene(floorScene(json::array({kQuadLight}), json::array({kBlocker}))).image;
    // The strata cut by the shadow edge make noise of about 1e-3 of the full irradiance.
    const double fullyLit = kKd * lightVisibleBeyond({0, 0, 0}, -0.5);
    expectPixelsMatch(
        image, kFloorCamera,
        [](const RayD& ray) -> std::optional<Radiance> {
            const Vec3d p = floorPoint(ray);
            const double E = kKd * lightVisibleBeyond(p, -p.x);
            return Radiance{E, E, E};
        },
        kRelativeTolerance, 2e-3 * fullyLit);

    // Across the middle row: black, then strictly between black and the unshadowed value, rising,
    // then lit.
    int umbra = 0, penumbra = 0, lit = 0;
    float previous = -1;
    for (int i = 0; i < kFloorCamera.width; ++i) {
        const double x = floorPoint(kFloorCamera.rayThroughPixelCentre(i, 2)).x;
        const float value = image.at(i, 2)[0];
        const double unshadowed = kKd * lightVisibleBeyond({x, 0, 0}, -0.5);
        if (x < -0.5) {
            EXPECT_EQ(value, 0) << "umbra, pixel " << i;
            ++umbra;
        } else if (x > -0.45 && x < 0.45) {
            EXPECT_GT(value, 0) << "penumbra, pixel " << i;
            EXPECT_LT(value, unshadowed) << "penumbra, pixel " << i;
            EXPECT_GT(value, previous)
                << "the penumbra brightens towards the lit side, pixel " << i;
            previous = value;
            ++penumbra;
        } else if (x > 0.5) {
            EXPECT_NEAR(value, unshadowed, kRelativeTolerance * unshadowed) << "lit, pixel " << i;
            ++lit;
        }
    }
    EXPECT_GE(umbra, 5);
    EXPECT_GE(penumbra, 20);
    EXPECT_GE(lit, 5);
}

TEST(CliAreaLight, SoftShadowsDependOnTheSeedButNotOnTheThreadCount) {
    json light = kQuadLight;
    light["samples"] = 4;
    json scene = floorScene(json::array({light}), json::array({kBlocker}));
    scene["render"]["spp"] = 4;
    const std::string oneThread = renderScene(scene, {"--threads", "1"}).bytes;
    EXPECT_TRUE(renderScene(scene, {"--threads", "2"}).bytes == oneThread) << "the files differ";
    EXPECT_FALSE(renderScene(scene, {"--threads", "2", "--seed", "5"}).bytes == oneThread)
        << "the seed picks the light samples";
}

// A camera at z = 3 looking at a 4 x 4 quad light in the plane z = 0 that fills its view.
const CameraModel kFacingCamera{
    .position = {0, 0, 3}, .lookAt = {0, 0, 0}, .width = 8, .height = 6};

json sceneWithQuadFacing(const std::string& edges) {
    json scene = json::parse(R"({ "background": 0.5, "ambient": 0.2, "lights": [
        { "type": "point", "position": [0, 0, 2], "intensity": 10 },
        { "type": "quad", "corner": [-2, -2, 0], "radiance": [1.5, 2, 2.5], )" +
                             edges + R"( } ] })");
    kFacingCamera.placeIn(scene);
    return scene;
}

TEST(CliAreaLight, AQuadLightSeenFromTheFrontIsItsRadiance) {
    const Image image =
        renderScene(sceneWithQuadFacing(R"("edge1": [4, 0, 0], "edge2": [0, 4, 0])")).image;
    expectPixelsMatch(
        image, kFacingCamera,
        [](const RayD&) {
            return std::optional<Radiance>({1.5, 2, 2.5});
        },
        0, 0);
}

TEST(CliAreaLight, AQuadLightSeenFromBehindIsBlackEvenUnderOtherLights) {
    // edge1 x edge2 points away from the camera.
    const Image image =
        renderScene(sceneWithQuadFacing(R"("edge1": [0, 4, 0], "edge2": [4, 0, 0])")).image;
    expectPixelsMatch(
        image, kFacingCamera, [](const RayD&) { return std::optional<Radiance>({}); }, 0, 0);
}

TEST(CliAreaLight, AMirrorShowsAQuadLightsFrontAsItsRadianceAndItsBackAsBlack) {
    // Looking steeply down at a perfect mirror floor, under a wide quad light at height 2: every
    // camera ray meets the mirror, and its reflection meets the quad from below.
    const CameraModel camera{.position = {0, 1, 0.5}, .lookAt = {0, 0, 0}, .vfovDegrees = 20};
    const auto render = [&](const std::string& edges) {
        json scene = json::parse(R"({ "background": 0.5, "ambient": 0,
            "materials": { "mirror": { "diffuse": 0, "reflection": 1 } },
            "objects": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                           "material": "mirror" } ],
            "lights": [ { "type": "quad", "corner": [-10, 2, -10], "radiance": [1.5, 2, 2.5], )" +
                                 edges + R"( } ] })");
        camera.placeIn(scene);
        return renderScene(scene).image;
    };
    // edge1 x edge2 = -y: the front faces the mirror.
    expectPixelsMatch(
        render(R"("edge1": [20, 0, 0], "edge2": [0, 0, 20])"), camera,
        [](const RayD&) {
            return std::optional<Radiance>({1.5, 2, 2.5});
        },
        0, 0);
    expectPixelsMatch(
        render(R"("edge1": [0, 0, 20], "edge2": [20, 0, 0])"), camera,
        [](const RayD&) { return std::optional<Radiance>({}); }, 0, 0);
}

TEST(CliAreaLight, ASphereLightIsSeenAsItsRadianceAndLightsTheFloorAsTheClosedFormSays) {
    // Radius 0.3 at height 1.5: E = pi L (r / d)^2 cos(beta) on the floor. The camera looks down
    // from beside it, seeing the floor and the sphere.
    const json light = json::parse(
        R"({ "type": "sphere", "center": [0, 1.5, 0], "radius": 0.3, "radiance": 4,
             "samples": 4096 })");
    const CameraModel camera{
        .position = {0, 3, 2}, .lookAt = {0, 0.5, 0}, .vfovDegrees = 50, .width = 24, .height = 18};
    json scene = floorScene(json::array({light}));
    camera.placeIn(scene);
    const Image image = renderScene(scene).image;
    const Vec3d center(0, 1.5, 0);
    int onSphere = 0;
    expectPixelsMatch(
        image, camera,
        [&](const RayD& ray) -> std::optional<Radiance> {
            if (const auto t = intersectSphere(ray, center, 0.3)) {
                if (std::abs(distanceToLine(center, ray) - 0.3) < 0.01) return std::nullopt;
                ++onSphere;
                return Radiance{kRadiance, kRadiance, kRadiance};
            }
            const Vec3d p = floorPoint(ray);
            const Vec3d toCenter = center - p;
            const double d2 = lengthSquared(toCenter);
            const double E =
                3.14159265358979323846 * kRadiance * 0.09 / d2 * dot(kUp, toCenter) / std::sqrt(d2);
            // The sphere's shadow is its own: no blocker.
            return Radiance{kKd * E, kKd * E, kKd * E};
        },
        kRelativeTolerance, 0);
    EXPECT_GT(onSphere, 4);
}

TEST(CliAreaLight, ASpotLightLightsItsConeOnly) {
    // Straight down from height 2, cone 20 degrees with no fade: E = I / d^2 cos inside the
    // circle of radius 2 tan(20) on the floor, nothing outside.
    const json spot = json::parse(R"({ "type": "spot", "position": [0, 2, 0],
        "look_at": [0, 0, 0], "intensity": 8, "cone_angle": 20, "cone_falloff": 0 })");
    const Image image = renderScene(floorScene(json::array({spot}))).image;
    const double radius = 2 * std::tan(20 * 3.14159265358979323846 / 180);
    int inside = 0;
    expectPixelsMatch(
        image, kFloorCamera,
        [&](const RayD& ray) -> std::optional<Radiance> {
            const Vec3d p = floorPoint(ray);
            const double r = std::hypot(p.x, p.z);
            if (std::abs(r - radius) < 1e-3) return std::nullopt;
            if (r > radius) return Radiance{};
            ++inside;
            const Vec3d toLight = Vec3d(0, 2, 0) - p;
            const double d2 = lengthSquared(toLight);
            const double E = kKd * 8 / d2 * toLight.y / std::sqrt(d2);
            return Radiance{E, E, E};
        },
        1e-4, 1e-7);
    EXPECT_GT(inside, 10);
}

}  // namespace
}  // namespace lancer::test
