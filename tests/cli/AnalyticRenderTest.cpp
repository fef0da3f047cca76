// Renders of small scenes whose every pixel has a closed form, on linear .pfm output.
//
// With one sample per pixel, lancer's sample goes through the pixel's centre, so the test can
// trace the same ray (in double precision, from the camera formula of the contract), find what it
// hits and evaluate the shading equation of the contract there.
//
// Tolerances: lancer computes in float; the hit point, distances, cosines and powers it derives
// each carry relative errors of a few 1e-7 (a pow(x, 40) multiplies its argument's error by 40).
// A relative tolerance of 1e-4 is far above that yet far below any real mistake (a wrong factor,
// a missing cosine, a wrong exponent or distance all change values by percent). Pixels within
// rounding distance of an edge (a silhouette, a shadow border) may legitimately fall on either
// side, so the oracles leave them unchecked.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ClosedForm.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr double kRelativeTolerance = 1e-4;
// For values that should be 0: a float sum of terms of order 1 is exact when they are all 0.
constexpr double kAbsoluteTolerance = 1e-7;

const Vec3d kOrigin{0, 0, 0};
const Vec3d kUp{0, 1, 0};

// Whether a ray passes within rounding distance of a sphere's silhouette.
bool nearSilhouette(const RayD& ray, const Vec3d& center, double radius) {
    return std::abs(distanceToLine(center, ray) - radius) < 1e-4 * radius;
}

// --- A plane under one light: Lambertian and Blinn-Phong ---

struct LightCase {
    std::string name;
    json light;
};

std::ostream& operator<<(std::ostream& out, const LightCase& c) {
    return out << c.name;
}

// The camera looks down at the origin of the plane y = 0, and every light sits where the mirror
// image of the camera is, so that the highlight is in the middle of the picture.
const CameraModel kCameraAbovePlane{.position = {0, 4, 4}, .lookAt = kOrigin, .vfovDegrees = 40};

const LightCase kLightCases[] = {
    {"PointLight",
     json::parse(R"({ "type": "point", "position": [0, 4, -4], "intensity": [40, 32, 24] })")},
    {"PointLightWithoutFalloff",
     json::parse(R"({ "type": "point", "position": [0, 4, -4], "intensity": [1, 0.8, 0.6],
                      "falloff": "none" })")},
    {"DirectionalLight",
     json::parse(
         R"({ "type": "directional", "direction": [0, -1, 1], "irradiance": [1, 0.8, 0.6] })")},
};

class CliPlaneUnderLight : public testing::TestWithParam<LightCase> {
protected:
    // The plane y = 0 made of `material`, under the light of the case, with no ambient light.
    static json sceneWithPlaneOf(const std::string& material) {
        json scene = json::parse(R"({
          "background": 0, "ambient": 0,
          "objects": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                         "material": "surface" } ]
        })");
        scene["materials"]["surface"] = json::parse(material);
        scene["lights"] = json::array({GetParam().light});
        kCameraAbovePlane.placeIn(scene);
        return scene;
    }

    static Vec3d pointOnPlane(const RayD& ray) {
        return ray.at(intersectPlane(ray, kOrigin, kUp).value());
    }

    static int pixelCount() { return kCameraAbovePlane.width * kCameraAbovePlane.height; }
};

TEST_P(CliPlaneUnderLight, LambertianPlaneIsKdTimesIrradianceTimesCosineAtEveryPixel) {
    const Radiance kd{0.5, 0.6, 0.7};
    const Image image = renderScene(sceneWithPlaneOf(R"({ "diffuse": [0.5, 0.6, 0.7] })")).image;

    const int checked = expectPixelsMatch(
        image, kCameraAbovePlane,
        [&](const RayD& ray) -> std::optional<Radiance> {
            const Incident in = incidentLight(GetParam().light, pointOnPlane(ray));
            return std::max(0.0, dot(kUp, in.towardsLight)) * (kd * in.irradiance);
        },
        kRelativeTolerance, kAbsoluteTolerance);
    EXPECT_EQ(checked, pixelCount()) << "the plane fills the picture";
}

TEST_P(CliPlaneUnderLight, BlinnPhongPlaneAddsTheHighlightKsTimesIrradianceTimesNdotHToTheN) {
    const Radiance kd{0.2, 0.3, 0.4}, ks{0.6, 0.5, 0.4};
    const double shininess = 40;
    const Image image = renderScene(sceneWithPlaneOf(R"({ "diffuse": [0.2, 0.3, 0.4],
        "specular": [0.6, 0.5, 0.4], "shininess": 40 })"))
                            .image;

    double largestHighlight = 0;  // of n.h^shininess, to be sure that the picture has a highlight
    const int checked = expectPixelsMatch(
        image, kCameraAbovePlane,
        [&](const RayD& ray) -> std::optional<Radiance> {
            const Incident in = incidentLight(GetParam().light, pointOnPlane(ray));
            const double cosTheta = dot(kUp, in.towardsLight);
            if (cosTheta <= 0) return Radiance{};
            const Vec3d h = normalize(in.towardsLight - ray.direction);
            const double highlight = std::pow(std::max(0.0, dot(kUp, h)), shininess);
            largestHighlight = std::max(largestHighlight, highlight);
            return cosTheta * (kd * in.irradiance) + highlight * (ks * in.irradiance);
        },
        kRelativeTolerance, kAbsoluteTolerance);
    EXPECT_EQ(checked, pixelCount());
    EXPECT_GT(largestHighlight, 0.9) << "the highlight's peak is in the picture";
}

INSTANTIATE_TEST_SUITE_P(Lights, CliPlaneUnderLight, testing::ValuesIn(kLightCases), CaseName());

// --- Shadows ---

// A sphere hangs between a point light and the plane y = 0.
struct ShadowScene {
    const json light =
        json::parse(R"({ "type": "point", "position": [0.5, 4, 0], "intensity": 20 })");
    const Vec3d lightPosition = vec3FromJson(light["position"]);
    const Vec3d sphereCenter{0, 1.5, 0.5};
    const double sphereRadius = 0.5;
    // Dyadic values, so that ka * ambient is exact in float and in double alike.
    const Radiance planeKd{0.5, 0.75, 1}, planeKa{0.5, 0.25, 1}, ambient{0.25, 0.25, 0.25};
    const Radiance sphereKd{0.5, 0.5, 0.5};

    json scene(const CameraModel& camera) const {
        json s = json::parse(R"({
          "background": 0, "ambient": 0.25,
          "materials": {
            "floor": { "diffuse": [0.5, 0.75, 1], "ambient": [0.5, 0.25, 1] },
            "ball": { "diffuse": 0.5 }
          },
          "objects": [
            { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" },
            { "type": "sphere", "center": [0, 1.5, 0.5], "radius": 0.5, "material": "ball" }
          ]
        })");
        s["lights"] = json::array({light});
        camera.placeIn(s);
        return s;
    }

    enum class Seen { Sphere, LitFloor, ShadowedFloor, Edge };

    Seen classify(const RayD& ray) const {
        if (nearSilhouette(ray, sphereCenter, sphereRadius)) return Seen::Edge;
        if (intersectSphere(ray, sphereCenter, sphereRadius)) return Seen::Sphere;
        const Vec3d p = ray.at(intersectPlane(ray, kOrigin, kUp).value());
        const double gap = distanceToSegment(sphereCenter, p, lightPosition) - sphereRadius;
        if (std::abs(gap) < 1e-4) return Seen::Edge;
        return gap < 0 ? Seen::ShadowedFloor : Seen::LitFloor;
    }

    Radiance lambert(const Vec3d& p, const Vec3d& n, const Radiance& kd) const {
        const Incident in = incidentLight(light, p);
        return std::max(0.0, dot(n, in.towardsLight)) * (kd * in.irradiance);
    }

    std::optional<Radiance> expected(const RayD& ray) const {
        switch (classify(ray)) {
            case Seen::Edge:
                return std::nullopt;
            case Seen::Sphere: {
                const Vec3d p = ray.at(*intersectSphere(ray, sphereCenter, sphereRadius));
                return sphereKd * ambient + lambert(p, (p - sphereCenter) / sphereRadius, sphereKd);
            }
            case Seen::ShadowedFloor:
                return planeKa * ambient;
            case Seen::LitFloor: {
                const Vec3d p = ray.at(*intersectPlane(ray, kOrigin, kUp));
                return planeKa * ambient + lambert(p, kUp, planeKd);
            }
        }
        return std::nullopt;
    }
};

TEST(CliShadow, ShadowedFloorHasAmbientOnlyExactlyAndTheRestIsLit) {
    const ShadowScene shadow;
    const CameraModel camera{.position = {0, 4, 4}, .lookAt = kOrigin, .vfovDegrees = 40};
    const Image image = renderScene(shadow.scene(camera)).image;

    expectPixelsMatch(
        image, camera, [&](const RayD& ray) { return shadow.expected(ray); }, kRelativeTolerance,
        kAbsoluteTolerance);

    // In the shadow, nothing but ka * ambient: exactly, since that product of dyadic numbers is
    // exact and any light leaking through would add to it.
    const Radiance kaTimesAmbient = shadow.planeKa * shadow.ambient;
    const Image::Rgb ambientOnly{static_cast<float>(kaTimesAmbient.r),
                                 static_cast<float>(kaTimesAmbient.g),
                                 static_cast<float>(kaTimesAmbient.b)};
    int shadowed = 0, lit = 0;
    for (int j = 0; j < camera.height; ++j)
        for (int i = 0; i < camera.width; ++i) {
            const ShadowScene::Seen seen = shadow.classify(camera.rayThroughPixelCentre(i, j));
            lit += seen == ShadowScene::Seen::LitFloor;
            if (seen != ShadowScene::Seen::ShadowedFloor) continue;
            ++shadowed;
            EXPECT_EQ(image.at(i, j), ambientOnly) << "at (" << i << ", " << j << ")";
        }
    EXPECT_GE(shadowed, 20) << "the picture shows the shadow";
    EXPECT_GE(lit, 200) << "and lit floor around it";
}

// --- Mirror ---

// A mirror sphere alone against the background: every reflected ray escapes and sees it.
struct MirrorCase {
    std::string name;
    double kd;     // diffuse of the mirror, lit by a directional light
    int maxDepth;  // 0: local shading only
};

std::ostream& operator<<(std::ostream& out, const MirrorCase& c) {
    return out << c.name;
}

class CliMirrorSphere : public testing::TestWithParam<MirrorCase> {};

TEST_P(CliMirrorSphere, ShowsKrTimesBackgroundWhenDepthAllowsPlusLocalShading) {
    const MirrorCase& param = GetParam();
    const Radiance kr{0.9, 0.8, 0.7}, background{0.2, 0.4, 0.6};
    const double radius = 1;
    const CameraModel camera{.position = {0, 0, 5}, .lookAt = kOrigin, .vfovDegrees = 40};

    json scene = json::parse(R"({
      "background": [0.2, 0.4, 0.6], "ambient": 0,
      "materials": { "mirror": { "reflection": [0.9, 0.8, 0.7] } },
      "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "mirror" } ],
      "lights": [ { "type": "directional", "direction": [-1, -1, -1], "irradiance": 1 } ]
    })");
    const json light = scene["lights"][0];
    scene["materials"]["mirror"]["diffuse"] = param.kd;
    camera.placeIn(scene);
    scene["render"]["max_depth"] = param.maxDepth;
    const Image image = renderScene(scene).image;

    int sphereHits = 0;
    expectPixelsMatch(
        image, camera,
        [&](const RayD& ray) -> std::optional<Radiance> {
            if (nearSilhouette(ray, kOrigin, radius)) return std::nullopt;
            const std::optional<double> t = intersectSphere(ray, kOrigin, radius);
            if (!t) return background;
            ++sphereHits;
            const Vec3d p = ray.at(*t);
            const Incident in = incidentLight(light, p);
            const Radiance local =
                (param.kd * std::max(0.0, dot(p / radius, in.towardsLight))) * in.irradiance;
            return param.maxDepth > 0 ? local + kr * background : local;
        },
        kRelativeTolerance, kAbsoluteTolerance);
    EXPECT_GE(sphereHits, 50) << "the sphere covers part of the picture";
}

INSTANTIATE_TEST_SUITE_P(Cases, CliMirrorSphere,
                         testing::Values(MirrorCase{"PureMirror", 0, 5},
                                         MirrorCase{"MaxDepth0ShowsNoReflection", 0.25, 0},
                                         MirrorCase{"MaxDepth1Reflects", 0.25, 1}),
                         CaseName());

// --- Adaptive depth control ---

// Two mirrors in turn: the camera sees mirror A, which sends every ray to mirror B, which sends
// it up into the background. Nothing is lit, so each pixel is kr_A kr_B times the background
// when the ray off B is traced, and black when adaptive depth control leaves it (its weight,
// kr_A kr_B channel by channel, under the bailout in every channel) or leaves the ray off A.
struct AdcCase {
    std::string name;
    double bailout;
    bool tracesRayOffB;
};

std::ostream& operator<<(std::ostream& out, const AdcCase& c) {
    return out << c.name;
}

class CliAdaptiveDepthControl : public testing::TestWithParam<AdcCase> {};

TEST_P(CliAdaptiveDepthControl, LeavesTheRaysThatCarryLessThanTheBailout) {
    const AdcCase& param = GetParam();
    // A looks down the view direction at 45 degrees and sends the rays along +x; B sends them up
    // and away from A, whose plane they then never meet again. The camera's narrow view keeps
    // every ray on that course.
    json scene = json::parse(R"({
      "camera": { "position": [0, 0, 0], "look_at": [0, 0, -1], "vfov": 10 },
      "render": { "width": 16, "height": 12, "spp": 1, "max_depth": 5 },
      "background": 1, "ambient": 0,
      "materials": {
        "a": { "diffuse": 0, "reflection": [0.5, 0.2, 0.2] },
        "b": { "diffuse": 0, "reflection": [0.5, 0.9, 0.2] }
      },
      "objects": [
        { "type": "plane", "point": [0, 0, -5], "normal": [1, 0, 1], "material": "a" },
        { "type": "plane", "point": [8, 0, 0], "normal": [-1, 0.70710678, 0.70710678],
          "material": "b" }
      ],
      "lights": []
    })");
    scene["render"]["adc_bailout"] = param.bailout;
    // kr_A kr_B: (0.25, 0.18, 0.04), largest 0.25; the product of the largest weights, 0.45,
    // is not the weight: a bailout of 0.3 leaves the ray.
    const Image::Rgb expected =
        param.tracesRayOffB ? Image::Rgb{0.25f, 0.18f, 0.04f} : Image::Rgb{0, 0, 0};
    // Radiosity traces its mirrors as whitted does (its solution is dark: nothing is lit).
    for (const std::string integrator : {"whitted", "radiosity"}) {
        scene["render"]["integrator"] = integrator;
        const Image image = renderScene(scene).image;
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(image.at(x, y)[c], expected[c], 1e-6)
                        << integrator << " at (" << x << ", " << y << ")";
    }
}

INSTANTIATE_TEST_SUITE_P(Cases, CliAdaptiveDepthControl,
                         testing::Values(AdcCase{"OffTracesEveryRay", 0, true},
                                         AdcCase{"BelowTheLargestChannelTraces", 0.24, true},
                                         AdcCase{"AboveEveryChannelLeavesTheRay", 0.3, false},
                                         AdcCase{"AboveTheFirstWeightLeavesBoth", 0.6, false}),
                         CaseName());

// --- Clear glass ---

TEST(CliGlass, Ior1GlassSphereChangesNothing) {
    // A floor and a back wall under a point light, with ambient light; then the same with a glass
    // sphere of ior 1 in front: no bending, no Fresnel reflection (F = 0 at ior 1), full
    // transmission, and a shadow ray through it keeps all the light.
    json scene = json::parse(R"({
      "background": [0.1, 0.2, 0.3], "ambient": 0.1,
      "materials": {
        "floor": { "diffuse": [0.6, 0.5, 0.4] },
        "wall": { "diffuse": [0.3, 0.5, 0.7], "specular": 0.3, "shininess": 20 },
        "clear": { "diffuse": 0, "transmission": 1, "ior": 1 }
      },
      "objects": [
        { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" },
        { "type": "plane", "point": [0, 0, -3], "normal": [0, 0, 1], "material": "wall" }
      ],
      "lights": [ { "type": "point", "position": [2, 5, 3], "intensity": 30 } ]
    })");
    const CameraModel camera{.position = {0, 2.5, 5},
                             .lookAt = {0, 0.8, 0},
                             .vfovDegrees = 40,
                             .width = 48,
                             .height = 36};
    camera.placeIn(scene);
    // Through the sphere and on to the floor is two bounces; 4 leaves room.
    scene["render"]["max_depth"] = 4;
    const Image withoutSphere = renderScene(scene).image;
    scene["objects"].push_back(json::parse(
        R"({ "type": "sphere", "center": [0, 1, 0], "radius": 1, "material": "clear" })"));
    const Image withSphere = renderScene(scene).image;

    // A ray through the sphere is re-spawned twice (offset by the hit point's error bound, about
    // 1e-7 relative) and its direction rounded on the way: it lands a few 1e-7 from where it
    // would have, and shading varies slowly, so values agree to about 1e-7 (a float's last bits).
    // 1e-5 absolute leaves room for other compilers' rounding yet is far below a missing shadow,
    // a reflection or a bent ray (values are about 0.1 to 1).
    EXPECT_LT(maxAbsoluteDifference(withSphere, withoutSphere), 1e-5);
}

// --- Emission ---

struct EmissionCase {
    std::string name;
    std::string object;  // the emitter, a JSON object of material "lamp"
    CameraModel camera;
    PixelOracle expected;
};

std::ostream& operator<<(std::ostream& out, const EmissionCase& c) {
    return out << c.name;
}

const Radiance kEmission{1, 2, 3};
const Radiance kBlack{};

// Whether the ray meets the triangle (-1,-1,0), (1,-1,0), (0,1,0) of the plane z = 0 well inside
// (true), well outside (false), or within rounding distance of an edge (no value).
std::optional<bool> hitsEmissiveTriangle(const RayD& ray) {
    const std::optional<double> t = intersectPlane(ray, kOrigin, {0, 0, 1});
    if (!t) return false;
    const Vec3d p = ray.at(*t);
    // Signed distances to the three edges, positive inside.
    const double margins[3] = {p.y + 1, (1 - 2 * p.x - p.y) / std::sqrt(5.0),
                               (1 + 2 * p.x - p.y) / std::sqrt(5.0)};
    const double nearest = *std::min_element(std::begin(margins), std::end(margins));
    if (std::abs(nearest) < 1e-4) return std::nullopt;
    return nearest > 0;
}

const std::string kEmissiveTriangle =
    R"({ "type": "triangle", "vertices": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], "material": "lamp" })";

const EmissionCase kEmissionCases[] = {
    {"SphereSeenFromOutside",
     R"({ "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "lamp" })",
     {.position = {0, 0, 5}, .lookAt = kOrigin},
     [](const RayD& ray) -> std::optional<Radiance> {
         if (nearSilhouette(ray, kOrigin, 1)) return std::nullopt;
         return intersectSphere(ray, kOrigin, 1) ? kEmission : kBlack;
     }},
    {"SphereSeenFromInside",
     R"({ "type": "sphere", "center": [0, 0, 0], "radius": 10, "material": "lamp" })",
     {.position = {0, 0, 0}, .lookAt = {0, 0, -1}},
     [](const RayD&) -> std::optional<Radiance> { return kEmission; }},
    // (v1 - v0) x (v2 - v0) points to +z, towards this camera.
    {"TriangleSeenFromItsFront",
     kEmissiveTriangle,
     {.position = {0, 0, 3}, .lookAt = kOrigin},
     [](const RayD& ray) -> std::optional<Radiance> {
         const std::optional<bool> inside = hitsEmissiveTriangle(ray);
         if (!inside) return std::nullopt;
         return *inside ? kEmission : kBlack;
     }},
    {"TriangleSeenFromBehindIsBlack",
     kEmissiveTriangle,
     {.position = {0, 0, -3}, .lookAt = kOrigin},
     [](const RayD&) -> std::optional<Radiance> { return kBlack; }},
};

class CliEmission : public testing::TestWithParam<EmissionCase> {};

TEST_P(CliEmission, EmitterShowsItsEmissionOnItsEmittingSidesOnly) {
    // No lights, no ambient light, black background: whatever is not emitted is black.
    json scene = json::parse(R"({
      "background": 0, "ambient": 0,
      "materials": { "lamp": { "diffuse": 0, "emission": [1, 2, 3] } }
    })");
    scene["objects"] = json::array({json::parse(GetParam().object)});
    GetParam().camera.placeIn(scene);
    const Image image = renderScene(scene).image;

    expectPixelsMatch(image, GetParam().camera, GetParam().expected, kRelativeTolerance,
                      kAbsoluteTolerance);
}

INSTANTIATE_TEST_SUITE_P(Emitters, CliEmission, testing::ValuesIn(kEmissionCases), CaseName());

}  // namespace
}  // namespace lancer::test
