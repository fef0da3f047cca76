// Loading scene files: a full valid scene, and one clear error, at the right line and column,
// for each kind of mistake.

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "IntersectInto.h"
#include "TestSupport.h"
#include "geometry/Shape.h"
#include "io/SceneLoader.h"
#include "lights/Light.h"
#include "materials/Material.h"
#include "scene/InputError.h"

namespace lancer {
namespace {

constexpr float kTolerance = 1e-6f;

// Every feature of the contract that this version supports.
const std::string kFullScene = R"({
  // Comments are allowed, /* of both kinds */
  "render": { "width": 320, "height": 240, "spp": 4, "max_depth": 3, "integrator": "whitted" },
  "camera": { "position": [0, 1, 6], "look_at": [0, 1, 0], "up": [0, 1, 0], "vfov": 40,
              "aperture": 0.1, "focus_distance": 6 },
  "background": [0.05, 0.06, 0.08],
  "ambient": 0.1,
  "materials": {
    "red":   { "diffuse": [0.8, 0.1, 0.1], "specular": 0.5, "shininess": 64 },
    "floor": { "diffuse": { "checker": { "even": 0.9, "odd": 0.1, "scale": 1.0 } } },
    "mirror":{ "diffuse": 0, "reflection": 0.95 },
    "glass": { "diffuse": 0, "specular": 1, "shininess": 200, "transmission": 1, "ior": 1.5 },
    "lamp":  { "diffuse": 0, "ambient": 0, "emission": [10, 10, 10] }
  },
  "objects": [
    { "type": "sphere",   "center": [0, 1, 0], "radius": 1, "material": "red" },
    { "type": "plane",    "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" },
    { "type": "triangle", "vertices": [[-1,0,-2], [1,0,-2], [0,2,-2]], "material": "glass",
      "normals": [[0,0,1],[0,0,1],[0,0,1]], "uvs": [[0,0],[1,0],[0.5,1]] },
    { "type": "sphere",   "center": [3, 1, 0], "radius": 0.5 }
  ],
  "lights": [
    { "type": "point", "position": [4, 6, 4], "intensity": [60, 60, 60] },
    { "type": "point", "position": [-4, 6, 4], "intensity": 5, "falloff": "none" },
    { "type": "directional", "direction": [-1, -1, -1], "irradiance": [1, 2, 3] }
  ]
})";

Scene load(const std::string& text, std::vector<std::string>& warnings) {
    return SceneLoader::loadString(text, "test.json", warnings);
}

TEST(SceneLoaderTest, LoadsTheRenderSettings) {
    std::vector<std::string> warnings;
    const Scene scene = load(kFullScene, warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(scene.settings().width, 320);
    EXPECT_EQ(scene.settings().height, 240);
    EXPECT_EQ(scene.settings().samplesPerPixel, 4);
    EXPECT_EQ(scene.settings().maxDepth, 3);
    EXPECT_EQ(scene.settings().integrator, "whitted");
}

TEST(SceneLoaderTest, LoadsTheFilterAndAdaptiveSampling) {
    const auto settingsOf = [](const std::string& render) {
        std::vector<std::string> warnings;
        return load(R"({ "render": )" + render + R"(, "camera": { "position": [0, 0, 1],
                      "look_at": [0, 0, 0] } })",
                    warnings)
            .settings();
    };
    const RenderSettings plain = settingsOf("{}");
    EXPECT_EQ(plain.filter.type, "box");
    EXPECT_FALSE(plain.filter.radius);
    EXPECT_FALSE(plain.adaptive);

    const RenderSettings named = settingsOf(R"({ "filter": "gaussian" })");
    EXPECT_EQ(named.filter.type, "gaussian");
    EXPECT_FALSE(named.filter.radius);
    const RenderSettings sized =
        settingsOf(R"({ "filter": { "type": "mitchell", "radius": 1.5 } })");
    EXPECT_EQ(sized.filter.type, "mitchell");
    EXPECT_EQ(sized.filter.radius, 1.5f);

    // max_spp is the render's budget, samplesPerPixel; min_spp defaults to 16, or less budget.
    const RenderSettings adaptive =
        settingsOf(R"({ "adaptive": { "min_spp": 8, "max_spp": 512, "threshold": 0.02 } })");
    ASSERT_TRUE(adaptive.adaptive);
    EXPECT_EQ(adaptive.samplesPerPixel, 512);
    EXPECT_EQ(adaptive.adaptive->minSamples, 8);
    EXPECT_FLOAT_EQ(adaptive.adaptive->threshold, 0.02f);
    const RenderSettings defaults = settingsOf(R"({ "spp": 64, "adaptive": {} })");
    ASSERT_TRUE(defaults.adaptive);
    EXPECT_EQ(defaults.samplesPerPixel, 64);
    EXPECT_EQ(defaults.adaptive->minSamples, 16);
    EXPECT_FLOAT_EQ(defaults.adaptive->threshold, 0.05f);
    const RenderSettings small = settingsOf(R"({ "spp": 4, "adaptive": {} })");
    EXPECT_EQ(small.adaptive->minSamples, 4);
}

TEST(SceneLoaderTest, LoadsColoursAsTriplesOrOneGreyNumber) {
    std::vector<std::string> warnings;
    const Scene scene = load(kFullScene, warnings);
    EXPECT_EQ(scene.background(), Color(0.05f, 0.06f, 0.08f));
    EXPECT_EQ(scene.ambient(), Color(0.1f));
}

TEST(SceneLoaderTest, LoadsTheCamera) {
    std::vector<std::string> warnings;
    const Scene scene = load(kFullScene, warnings);
    // The lens centre gives the pinhole ray; the image centre looks at look_at.
    const Ray ray = *scene.camera().generateRay(160, 120, 320, 240, Vec2(0.5f, 0.5f));
    EXPECT_EQ(ray.origin, Vec3(0, 1, 6));
    EXPECT_VEC3_NEAR(ray.direction, Vec3(0, 0, -1), kTolerance);
    // Aperture 0.1: other lens samples start elsewhere on the lens.
    const Ray lensRay = *scene.camera().generateRay(160, 120, 320, 240, Vec2(0.9f, 0.5f));
    EXPECT_NEAR(length(lensRay.origin - Vec3(0, 1, 6)), 0.08f, kTolerance);
}

TEST(SceneLoaderTest, LoadsTheLights) {
    std::vector<std::string> warnings;
    const Scene scene = load(kFullScene, warnings);
    ASSERT_EQ(scene.lights().size(), 3u);
    const Vec3 p(0, 0, 0);
    const Vec2 u(0.5f, 0.5f);
    // Inverse square: 60 / |(4, 6, 4)|^2 = 60 / 68.
    const LightSample point = scene.lights()[0]->sample(p, u);
    EXPECT_NEAR(point.irradiance.r, 60.0f / 68, kTolerance);
    EXPECT_VEC3_NEAR(point.wi, normalize(Vec3(4, 6, 4)), kTolerance);
    // "falloff": "none": the intensity at any distance; a single number is grey.
    EXPECT_EQ(scene.lights()[1]->sample(p, u).irradiance, Color(5));
    const LightSample directional = scene.lights()[2]->sample(p, u);
    EXPECT_EQ(directional.irradiance, Color(1, 2, 3));
    EXPECT_VEC3_NEAR(directional.wi, normalize(Vec3(1, 1, 1)), kTolerance);
    EXPECT_TRUE(directional.atInfinity);
}

TEST(SceneLoaderTest, LoadsTheObjects) {
    std::vector<std::string> warnings;
    const Scene scene = load(kFullScene, warnings);
    struct Probe {
        Ray ray;
        Vec3 expectedPoint;
    };
    for (const Probe& probe : {
             Probe{{Vec3(0, 1, 6), Vec3(0, 0, -1)}, Vec3(0, 1, 1)},    // the red sphere
             Probe{{Vec3(0, 5, 3), Vec3(0, -1, 0)}, Vec3(0, 0, 3)},    // the floor
             Probe{{Vec3(0, 1, -1), Vec3(0, 0, -1)}, Vec3(0, 1, -2)},  // the triangle
             Probe{{Vec3(3, 1, 6), Vec3(0, 0, -1)},
                   Vec3(3, 1, 0.5f)},  // the default-material sphere
         }) {
        Hit hit;
        ASSERT_TRUE(test::intersectInto(scene, probe.ray, kInfinity, hit));
        EXPECT_VEC3_NEAR(hit.p, probe.expectedPoint, kTolerance);
    }
}

TEST(SceneLoaderTest, AcceptsEveryIntegratorName) {
    for (const std::string name : {"whitted", "path", "radiosity"}) {
        std::string text = kFullScene;
        text.replace(text.find("\"whitted\""), 9, "\"" + name + "\"");
        std::vector<std::string> warnings;
        EXPECT_EQ(load(text, warnings).settings().integrator, name);
    }
}

// "line:column" of the character at `offset` in `text`, both from 1.
std::string lineAndColumn(const std::string& text, std::size_t offset) {
    int line = 1;
    std::size_t lineStart = 0;
    for (std::size_t i = 0; i < offset; ++i) {
        if (text[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    }
    return std::to_string(line) + ":" + std::to_string(offset - lineStart + 1);
}

TEST(SceneLoaderTest, ZeroAreaTriangleIsDroppedWithAWarning) {
    const std::string text = R"({
  "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
  "objects": [
    { "type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]] },
    { "type": "sphere", "center": [0, 0, 0], "radius": 0.5 }
  ]
})";
    std::vector<std::string> warnings;
    const Scene scene = load(text, warnings);
    ASSERT_EQ(warnings.size(), 1u);
    // At the "vertices" value.
    const std::string prefix =
        "test.json:" + lineAndColumn(text, text.find("[[0, 0, 0]")) + ": warning: ";
    EXPECT_EQ(warnings[0].rfind(prefix, 0), 0u) << warnings[0] << "\nexpected: " << prefix;
    EXPECT_NE(warnings[0].find("zero area"), std::string::npos) << warnings[0];
    Hit hit;  // the rest of the scene is there
    EXPECT_TRUE(test::intersectInto(scene, {Vec3(0, 0, 5), Vec3(0, 0, -1)}, kInfinity, hit));
}

// --- errors ---

// A scene with one of each kind of thing, in which the cases below make one mistake each.
const std::string kBaseScene = R"({
  "render": { "width": 64, "height": 48, "integrator": "whitted" },
  "camera": { "position": [0, 1, 6], "look_at": [0, 1, 0], "up": [0, 1, 0], "vfov": 40 },
  "materials": { "glass": { "transmission": 1, "ior": 1.5 }, "red": { "diffuse": [0.8, 0.1, 0.1] } },
  "objects": [
    { "type": "sphere", "center": [0, 1, 0], "radius": 1, "material": "glass" },
    { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "red" },
    { "type": "triangle", "vertices": [[-1,0,-2], [1,0,-2], [0,2,-2]], "normals": [[0,0,1],[0,0,1],[0,0,1]], "uvs": [[0,0],[1,0],[0.5,1]] }
  ],
  "lights": [ { "type": "point", "position": [4, 6, 4], "intensity": 60, "falloff": "none" } ]
})";

struct ErrorCase {
    const char* name;
    const char* original;     // text of kBaseScene to replace (its first occurrence)
    const char* replacement;  // the mistake
    // Where the error points: the first occurrence of this text from the replacement on, or
    // from the start of the scene for an error at an object that encloses the replacement.
    const char* errorAt;
    std::vector<std::string> mentions;  // what the message must say
    bool errorAtEnclosingObject = false;
};

void PrintTo(const ErrorCase& c, std::ostream* out) {
    *out << c.name;
}

class SceneLoaderErrorTest : public testing::TestWithParam<ErrorCase> {};

TEST_P(SceneLoaderErrorTest, ReportsTheMistakeWhereItIs) {
    const ErrorCase& c = GetParam();
    std::string text = kBaseScene;
    const std::size_t at = text.find(c.original);
    ASSERT_NE(at, std::string::npos) << "the base scene has no " << c.original;
    text.replace(at, std::string(c.original).size(), c.replacement);
    const std::size_t errorAt = text.find(c.errorAt, c.errorAtEnclosingObject ? 0 : at);
    ASSERT_NE(errorAt, std::string::npos);
    const std::string expectedPrefix = "test.json:" + lineAndColumn(text, errorAt) + ": error: ";

    std::vector<std::string> warnings;
    try {
        load(text, warnings);
        FAIL() << "no error for:\n" << text;
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(expectedPrefix, 0), 0u)
            << "message: " << message << "\nexpected it to start with: " << expectedPrefix;
        EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
        for (const std::string& mention : c.mentions)
            EXPECT_NE(message.find(mention), std::string::npos)
                << "message: " << message << "\ndoes not mention: " << mention;
    }
}

std::string caseName(const testing::TestParamInfo<ErrorCase>& param) {
    return param.param.name;
}

INSTANTIATE_TEST_SUITE_P(
    Mistakes, SceneLoaderErrorTest,
    testing::Values(
        // Unknown keys, at the key, with a suggestion.
        ErrorCase{"UnknownTopLevelKey",
                  "\"materials\"",
                  "\"matrials\"",
                  "\"matrials\"",
                  {"\"matrials\"", "did you mean \"materials\""}},
        ErrorCase{"UnknownSphereKey",
                  "\"radius\": 1",
                  "\"radus\": 1",
                  "\"radus\"",
                  {"\"radus\"", "did you mean \"radius\""}},
        ErrorCase{"UnknownMaterialKey",
                  "\"transmission\": 1",
                  "\"transmision\": 1",
                  "\"transmision\"",
                  {"\"transmision\"", "did you mean \"transmission\""}},
        ErrorCase{"UnknownCameraKey",
                  "\"vfov\": 40",
                  "\"fov\": 40",
                  "\"fov\"",
                  {"\"fov\"", "did you mean \"vfov\""}},
        // Names that refer to nothing, at the value, with a suggestion.
        ErrorCase{"UndefinedMaterial",
                  "\"material\": \"glass\"",
                  "\"material\": \"glas\"",
                  "\"glas\"",
                  {"\"glas\"", "did you mean \"glass\""}},
        ErrorCase{"UnknownObjectType",
                  "\"type\": \"sphere\"",
                  "\"type\": \"sphre\"",
                  "\"sphre\"",
                  {"\"sphre\"", "did you mean \"sphere\""}},
        ErrorCase{"UnknownLightType",
                  "\"type\": \"point\"",
                  "\"type\": \"laser\"",
                  "\"laser\"",
                  {"\"laser\""}},
        ErrorCase{"BadIntegratorName",
                  "\"whitted\"",
                  "\"whited\"",
                  "\"whited\"",
                  {"\"whited\"", "did you mean \"whitted\""}},
        ErrorCase{"BadFalloff",
                  "\"falloff\": \"none\"",
                  "\"falloff\": \"inverse-square\"",
                  "\"inverse-square\"",
                  {"\"inverse-square\"", "did you mean \"inverse_square\""}},
        // Wrong types, at the value, naming the key.
        ErrorCase{"RadiusAsString", "\"radius\": 1", "\"radius\": \"1\"", "\"1\"", {"\"radius\""}},
        ErrorCase{"CenterOfTwoNumbers",
                  "\"center\": [0, 1, 0]",
                  "\"center\": [0, 1]",
                  "[0, 1]",
                  {"\"center\""}},
        ErrorCase{"CenterWithABoolean",
                  "\"center\": [0, 1, 0]",
                  "\"center\": [0, true, 0]",
                  "true",
                  {"\"center\""}},
        ErrorCase{"WidthNotWhole", "\"width\": 64", "\"width\": 64.5", "64.5", {"\"width\""}},
        ErrorCase{"ColourOfTwoNumbers",
                  "\"intensity\": 60",
                  "\"intensity\": [60, 60]",
                  "[60, 60]",
                  {"\"intensity\""}},
        ErrorCase{
            "LightsNotAnArray",
            "\"lights\": [ { \"type\": \"point\", \"position\": [4, 6, 4], \"intensity\": 60, "
            "\"falloff\": \"none\" } ]",
            "\"lights\": 7",
            "7",
            {"\"lights\""}},
        ErrorCase{"MaterialNotAnObject", "\"red\": {", "\"red\": 3, \"blue\": {", "3", {"\"red\""}},
        ErrorCase{"TriangleOfTwoVertices",
                  "[[-1,0,-2], [1,0,-2], [0,2,-2]]",
                  "[[-1,0,-2], [1,0,-2]]",
                  "[[-1",
                  {"\"vertices\""}},
        ErrorCase{"UvOfThreeNumbers",
                  "[[0,0],[1,0],[0.5,1]]",
                  "[[0,0],[1,0,2],[0.5,1]]",
                  "[1,0,2]",
                  {"\"uvs\""}},
        // Values out of range, at the value, naming the key.
        ErrorCase{"NegativeRadius", "\"radius\": 1", "\"radius\": -1", "-1", {"\"radius\""}},
        ErrorCase{"ZeroRadius", "\"radius\": 1", "\"radius\": 0", "0", {"\"radius\""}},
        ErrorCase{"ZeroNormal",
                  "\"normal\": [0, 1, 0]",
                  "\"normal\": [0, 0, 0]",
                  "[0, 0, 0]",
                  {"\"normal\""}},
        ErrorCase{"ZeroVertexNormal",
                  "\"normals\": [[0,0,1],[0,0,1]",
                  "\"normals\": [[0,0,1],[0,0,0]",
                  "[0,0,0]",
                  {"\"normals\""}},
        ErrorCase{"NegativeColour",
                  "\"diffuse\": [0.8, 0.1, 0.1]",
                  "\"diffuse\": [0.8, -0.1, 0.1]",
                  "-0.1",
                  {"\"diffuse\""}},
        ErrorCase{"ZeroWidth", "\"width\": 64", "\"width\": 0", "0", {"\"width\""}},
        ErrorCase{"ZeroIor", "\"ior\": 1.5", "\"ior\": 0", "0", {"\"ior\""}},
        ErrorCase{"FieldOfView180", "\"vfov\": 40", "\"vfov\": 180", "180", {"\"vfov\""}},
        ErrorCase{"CameraLookingAtItself",
                  "\"look_at\": [0, 1, 0]",
                  "\"look_at\": [0, 1, 6]",
                  "[0, 1, 6]",
                  {"\"look_at\""}},
        ErrorCase{
            "UpAlongTheView", "\"up\": [0, 1, 0]", "\"up\": [0, 0, 1]", "[0, 0, 1]", {"\"up\""}},
        // Missing things, at the object that lacks them.
        ErrorCase{"MissingCamera",
                  "  \"camera\": { \"position\": [0, 1, 6], \"look_at\": [0, 1, 0], \"up\": [0, 1, "
                  "0], \"vfov\": 40 },\n",
                  "",
                  "{",
                  {"\"camera\""},
                  true},
        ErrorCase{"MissingLookAt",
                  "{ \"position\": [0, 1, 6], \"look_at\": [0, 1, 0],",
                  "{ \"position\": [0, 1, 6],",
                  "{",
                  {"\"look_at\""}},
        ErrorCase{
            "MissingRadius", "\"radius\": 1, ", "", "{ \"type\": \"sphere\"", {"\"radius\""}, true},
        ErrorCase{"MissingObjectType", "{ \"type\": \"plane\", ", "{ ", "{", {"\"type\""}},
        // A syntax error is reported by the JSON reader, at the token it did not expect.
        ErrorCase{"MissingComma", "\"radius\": 1,", "\"radius\": 1", "\"material\"", {}},
        ErrorCase{"UnknownAnimationKey",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"fsp\": 12 }, \"objects\": [\n    { \"type\": "
                  "\"sphere\", \"name\": \"ball\", \"center\": [0, 1, 0],",
                  "\"fsp\"",
                  {"\"fsp\"", "did you mean \"fps\""}},
        ErrorCase{"AnimationWithoutFrames",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"fps\": 12 }, \"objects\": [\n    { \"type\": \"sphere\", "
                  "\"name\": \"ball\", \"center\": [0, 1, 0],",
                  "{ \"fps\"",
                  {"\"frames\""}},
        ErrorCase{"UnknownInterpolation",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"interpolation\": \"smoth\" }, \"objects\": "
                  "[\n    { \"type\": \"sphere\", \"name\": \"ball\", \"center\": [0, 1, 0],",
                  "\"smoth\"",
                  {"did you mean \"smooth\""}},
        ErrorCase{"KeyframeBeyondTheFrames",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"camera\": [{ \"frame\": 9, \"vfov\": 30 }] }, "
                  "\"objects\": [\n    { \"type\": \"sphere\", \"name\": \"ball\", \"center\": [0, "
                  "1, 0],",
                  "9",
                  {"\"frame\"", "at most 4"}},
        ErrorCase{"KeyframesOutOfOrder",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"camera\": [{ \"frame\": 3, \"vfov\": 30 }, { "
                  "\"frame\": 2, \"vfov\": 50 }] }, \"objects\": [\n    { \"type\": \"sphere\", "
                  "\"name\": \"ball\", \"center\": [0, 1, 0],",
                  "50",
                  {"order of their frames", "frame 2 follows frame 3"}},
        ErrorCase{"KeyframeOfAnotherShape",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"camera\": [{ \"frame\": 1, \"position\": [0, "
                  "1, 6] }, { \"frame\": 4, \"position\": [0, 1] }] }, \"objects\": [\n    { "
                  "\"type\": \"sphere\", \"name\": \"ball\", \"center\": [0, 1, 0],",
                  "[0, 1] }",
                  {"\"position\"", "shape of its first keyframe"}},
        ErrorCase{"UnknownKeyInACameraKeyframe",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"camera\": [{ \"frame\": 1, \"fov\": 30 }] }, "
                  "\"objects\": [\n    { \"type\": \"sphere\", \"name\": \"ball\", \"center\": [0, "
                  "1, 0],",
                  "\"fov\"",
                  {"\"fov\"", "did you mean \"vfov\""}},
        ErrorCase{"CameraTypeKeyframed",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"camera\": [{ \"frame\": 1, \"type\": "
                  "\"fisheye\" }] }, \"objects\": [\n    { \"type\": \"sphere\", \"name\": "
                  "\"ball\", \"center\": [0, 1, 0],",
                  "\"type\"",
                  {"\"type\" cannot change"}},
        ErrorCase{"CameraKeyframeWithoutKeys",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"camera\": [{ \"frame\": 1 }] }, \"objects\": "
                  "[\n    { \"type\": \"sphere\", \"name\": \"ball\", \"center\": [0, 1, 0],",
                  "{ \"frame\": 1 }",
                  {"at least one of the camera"}},
        ErrorCase{"AnimatedCameraLookingAtItself",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"camera\": [{ \"frame\": 1, \"look_at\": [0, "
                  "1, 6] }] }, \"objects\": [\n    { \"type\": \"sphere\", \"name\": \"ball\", "
                  "\"center\": [0, 1, 0],",
                  "[0, 1, 6] }",
                  {"\"look_at\" is the camera's own"}},
        ErrorCase{"BadKeyframedTransform",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"objects\": { \"ball\": [{ \"frame\": 1, "
                  "\"transform\": { \"rotate\": [0, 1, 0] } }] } }, \"objects\": [\n    { "
                  "\"type\": \"sphere\", \"name\": \"ball\", \"center\": [0, 1, 0],",
                  "[0, 1, 0] }",
                  {"\"rotate\" must be"}},
        ErrorCase{"UnknownKeyInAnObjectKeyframe",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"objects\": { \"ball\": [{ \"frame\": 1, "
                  "\"transfrom\": {} }] } }, \"objects\": [\n    { \"type\": \"sphere\", \"name\": "
                  "\"ball\", \"center\": [0, 1, 0],",
                  "\"transfrom\"",
                  {"did you mean \"transform\""}},
        ErrorCase{"AnimatedObjectWithoutKeyframes",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"objects\": { \"ball\": [] } }, \"objects\": "
                  "[\n    { \"type\": \"sphere\", \"name\": \"ball\", \"center\": [0, 1, 0],",
                  "[]",
                  {"\"ball\" has no keyframe"}},
        ErrorCase{"AnimatedNameOfNoObject",
                  "\"objects\": [\n    { \"type\": \"sphere\", \"center\": [0, 1, 0],",
                  "\"animation\": { \"frames\": 4, \"objects\": { \"bal\": [{ \"frame\": 1, "
                  "\"transform\": { \"translate\": [1, 0, 0] } }] } }, \"objects\": [\n    { "
                  "\"type\": \"sphere\", \"name\": \"ball\", \"center\": [0, 1, 0],",
                  "\"bal\"",
                  {"no object has that \"name\"", "did you mean \"ball\""}},
        ErrorCase{"NameGivenTwice",
                  "\"material\": \"glass\" },\n    { \"type\": \"plane\", ",
                  "\"material\": \"glass\", \"name\": \"x\" },\n    { \"type\": \"plane\", "
                  "\"name\": \"x\", ",
                  "\"name\": \"x\", ",
                  {"\"x\" is already given to the object at test.json:6:"}}),
    caseName);

}  // namespace
}  // namespace lancer
