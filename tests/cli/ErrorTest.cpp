// Every error of the contract: the exit status, one line on stderr that says where and what
// ("file:line:col: error: ..." for a scene file), and no output file (nor temporary file) left
// behind; an output file that was there before the failing run is left as it was.

#include <gtest/gtest.h>

#include <algorithm>

#include "LancerRun.h"

namespace lancer::test {
namespace {

constexpr int kBadInput = 2;
constexpr int kFailure = 1;

// A valid scene; each scene case edits one fragment of it.
const std::string kValidScene = R"({
  "render": { "width": 8, "height": 6, "spp": 1, "max_depth": 3 },
  "camera": { "position": [0, 1, 5], "look_at": [0, 0, 0], "vfov": 40 },
  "materials": {
    "glass": { "diffuse": 0, "transmission": 1, "ior": 1.5 },
    "floor": { "diffuse": { "checker": { "even": 0.9, "odd": 0.1, "scale": 1 } } }
  },
  "objects": [
    { "type": "sphere", "center": [0, 1, 0], "radius": 1, "material": "glass" },
    { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" }
  ],
  "lights": [
    { "type": "point", "position": [2, 5, 3], "intensity": 40 }
  ]
}
)";

// The project's sky, for the environment's cases whose map must be read.
const std::string kSky = LANCER_SOURCE_DIR "/scenes/skies/sky.hdr";
// A model without normals, for the cases of "smooth".
const std::string kTeapot = LANCER_SOURCE_DIR "/scenes/models/utah_teapot/teapot.obj";

struct ErrorCase {
    std::string name{};
    // The scene file is kValidScene with `replace` replaced by `with`, in which '@' marks where
    // the message must place the error ("scene.json:LINE:COLUMN: error: ") and is then removed.
    // Without an edit, the scene is valid and the message must start with `prefix`.
    std::string replace{}, with{};
    std::string prefix{};
    std::vector<std::string> mentions{};   // fragments that the message must contain
    std::vector<std::string> arguments{};  // options after "scene.json -o OUTPUT"
    int exitStatus = kBadInput;
    std::string output = "out.png";
    bool writeScene = true;        // false: there is no scene file
    bool outputIsAFolder = false;  // out.png exists as a folder, so that the final rename fails
};

std::ostream& operator<<(std::ostream& out, const ErrorCase& c) {
    return out << c.name;
}

struct SceneFile {
    std::string text;
    std::string messagePrefix;  // what the error message must start with
};

SceneFile sceneFileOf(const ErrorCase& c) {
    if (c.replace.empty()) return {kValidScene, c.prefix};
    std::string text = kValidScene;
    const std::size_t at = text.find(c.replace);
    const std::size_t marker = c.with.find('@');
    if (at == std::string::npos || marker == std::string::npos)
        throw std::logic_error("bad test case " + c.name);
    text.replace(at, c.replace.size(), std::string(c.with).erase(marker, 1));
    const std::size_t errorAt = at + marker;
    const std::size_t lineStart = text.rfind('\n', errorAt - 1) + 1;  // npos + 1 == 0
    const auto line = std::count(text.begin(), text.begin() + static_cast<long>(errorAt), '\n') + 1;
    return {text, "scene.json:" + std::to_string(line) + ":" +
                      std::to_string(errorAt - lineStart + 1) + ": error: "};
}

class CliError : public testing::TestWithParam<ErrorCase> {
protected:
    // Runs the case in a fresh folder (holding `preexistingOutput` as the output file, unless
    // empty); checks the exit status and the message, and returns the folder's listing after.
    std::vector<std::string> runCase(const std::string& preexistingOutput) {
        const ErrorCase& c = GetParam();
        const TempFolder folder;
        const SceneFile scene = sceneFileOf(c);
        if (c.writeScene) folder.write("scene.json", scene.text);
        if (c.outputIsAFolder) fs::create_directory(folder / c.output);
        if (!preexistingOutput.empty()) folder.write(c.output, preexistingOutput);

        std::vector<std::string> arguments{"scene.json", "-o", c.output};
        arguments.insert(arguments.end(), c.arguments.begin(), c.arguments.end());
        const RunResult run = runLancer(arguments, folder.path());

        EXPECT_EQ(run.exitStatus, c.exitStatus) << run;
        const std::vector<std::string> lines = run.errorLines();
        EXPECT_EQ(lines.size(), 1u) << "one line on stderr, got:\n" << run.standardError;
        if (!lines.empty()) {
            const std::string& message = lines.front();
            EXPECT_EQ(message.rfind(scene.messagePrefix, 0), 0u)
                << "the message starts with \"" << scene.messagePrefix << "\": " << message;
            for (const std::string& fragment : c.mentions)
                EXPECT_NE(message.find(fragment), std::string::npos)
                    << "the message mentions " << fragment << ": " << message;
        }
        if (!preexistingOutput.empty()) {
            EXPECT_EQ(readFile(folder / c.output), preexistingOutput)
                << "the output that was there before is left as it was";
        }
        return folder.entries();
    }

    // What the folder held before the run.
    static std::vector<std::string> inputs() {
        const ErrorCase& c = GetParam();
        std::vector<std::string> names;
        if (c.writeScene) names.push_back("scene.json");
        if (c.outputIsAFolder) names.push_back(c.output);
        std::sort(names.begin(), names.end());
        return names;
    }
};

TEST_P(CliError, ExitsWithOneLineNamingTheFaultAndWritesNothing) {
    EXPECT_EQ(runCase(""), inputs()) << "no output file, no temporary file";
}

// The cases whose output file can exist before the run: its folder exists and it is a file.
class CliErrorWithPreexistingOutput : public CliError {};

TEST_P(CliErrorWithPreexistingOutput, LeavesItUndamaged) {
    std::vector<std::string> expected = inputs();
    expected.push_back(GetParam().output);
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(runCase("an image from an earlier run\n"), expected);
}

// A render this big would take hours: a case that uses it shows that its error is found before
// rendering starts (the run is killed as a failure after kRunTimeout).
const std::vector<std::string> kHugeRender{"--width", "8000", "--height", "8000", "--spp", "4096"};

const ErrorCase kErrorCases[] = {
    // --- the scene file: syntax ---
    // Syntax errors are told as the likely mistake (see JsonSyntaxTest for every kind).
    {.name = "MissingComma",
     .replace = R"("spp": 1, "max_depth")",
     .with = R"("spp": 1 @"max_depth")",
     .mentions = {"missing comma after the value on line 2?"}},
    {.name = "MissingCommaAtTheEndOfALine",
     .replace = "\"vfov\": 40 },\n  \"materials\"",
     .with = "\"vfov\": 40 }\n  @\"materials\"",
     .mentions = {"missing comma after the value on line 3?"}},
    // A trailing comma is accepted; two are not.
    {.name = "TwoTrailingCommas",
     .replace = "40 }\n  ]",
     .with = "40 },@,\n  ]",
     .mentions = {"one comma too many?"}},
    // At the end of the input, which is just past the last character.
    {.name = "TruncatedFile",
     .replace = "  ]\n}\n",
     .with = "  ]@\n",
     .mentions = {"missing '}' to close the '{' on line 1?"}},
    {.name = "ArrayClosedByABrace",
     .replace = R"("look_at": [0, 0, 0])",
     .with = R"("look_at": [0, 0, 0@})",
     .mentions = {"'}' cannot close the '[' on line 3: missing ']'?"}},
    {.name = "UnquotedKey",
     .replace = R"("vfov": 40)",
     .with = R"(@vfov: 40)",
     .mentions = {R"(keys go in double quotes: "vfov" instead of vfov)"}},
    {.name = "SingleQuotes",
     .replace = R"("material": "glass")",
     .with = R"("material": @'glass')",
     .mentions = {"double quotes", "not single quotes"}},
    {.name = "TextAfterTheScene",
     .replace = "  ]\n}\n",
     .with = "  ]\n}\n@}\n",
     .mentions = {"text after the end of the scene, whose outer brackets closed on line 15"}},
    // --- unknown keys, names and types ---
    {.name = "UnknownKeyInSphere",
     .replace = R"("radius": 1)",
     .with = R"(@"raduis": 1)",
     .mentions = {R"("raduis")", R"(did you mean "radius"?)"}},
    {.name = "UnknownTopLevelKey",
     .replace = R"("lights")",
     .with = R"(@"light")",
     .mentions = {R"("light")", R"(did you mean "lights"?)"}},
    {.name = "UnknownKeyInMaterial",
     .replace = R"("transmission": 1)",
     .with = R"(@"transmision": 1)",
     .mentions = {R"("transmision")", R"(did you mean "transmission"?)"}},
    {.name = "UndefinedMaterial",
     .replace = R"("material": "glass")",
     .with = R"("material": @"glas")",
     .mentions = {R"(material "glas" is not defined)", R"(did you mean "glass"?)"}},
    {.name = "UnknownObjectType",
     .replace = R"("type": "sphere")",
     .with = R"("type": @"sphear")",
     .mentions = {R"("sphear")", R"(did you mean "sphere"?)"}},
    {.name = "UnknownLightType",
     .replace = R"("type": "point")",
     .with = R"("type": @"pont")",
     .mentions = {R"("pont")", R"(did you mean "point"?)"}},
    {.name = "DiskInnerRadiusNotBelowItsRadius",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0], "radius": 1,
                  "inner_radius": @1 }, { "type": "sphere")",
     .mentions = {R"("inner_radius" must be less than "radius")"}},
    {.name = "BoxMaxNotAboveItsMinOnEveryAxis",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "box", "min": [0, 0, 0], "max": @[1, 0, 1] }, { "type": "sphere")",
     .mentions = {R"("max" must be greater than "min" on every axis)"}},
    {.name = "CylinderTopAtItsBase",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "cylinder", "base": [0, 1, 0], "top": @[0, 1, 0], "radius": 1 },
                { "type": "sphere")",
     .mentions = {R"("top" must differ from "base")"}},
    {.name = "ConeOfTwoZeroRadii",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "cone", "base": [0, 0, 0], "base_radius": 0, "top": [0, 1, 0],
                  "top_radius": @0 }, { "type": "sphere")",
     .mentions = {R"("base_radius" and "top_radius" cannot both be 0)"}},
    {.name = "TorusMinorRadiusNotBelowItsMajorRadius",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "torus", "major_radius": 1, "minor_radius": @1 }, { "type": "sphere")",
     .mentions = {R"("minor_radius" must be less than "major_radius")"}},
    {.name = "TorusOfZeroAxis",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "torus", "major_radius": 1, "minor_radius": 0.5, "axis": @[0, 0, 0] },
                { "type": "sphere")",
     .mentions = {R"("axis" must be a non-zero direction)"}},
    {.name = "TorusOfZeroMinorRadius",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "torus", "major_radius": 1, "minor_radius": @0 }, { "type": "sphere")",
     .mentions = {R"("minor_radius")"}},
    {.name = "CsgUnknownOperation",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "csg", "operation": @"subtract", "objects": [] }, { "type": "sphere")",
     .mentions = {R"(unknown operation "subtract")", R"("union", "intersection" or "difference")"}},
    {.name = "CsgWithoutOperation",
     .replace = R"({ "type": "sphere")",
     .with = R"(@{ "type": "csg", "objects": [] }, { "type": "sphere")",
     .mentions = {R"(a csg needs "operation")"}},
    {.name = "CsgOfOneObject",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "csg", "operation": "union",
                  "objects": @[ { "type": "sphere", "center": [0, 0, 0], "radius": 1 } ] },
                { "type": "sphere")",
     .mentions = {R"(a csg combines at least two objects, got 1)"}},
    {.name = "CsgOfAPlane",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "csg", "operation": "difference", "objects": [
                  { "type": "sphere", "center": [0, 0, 0], "radius": 1 },
                  @{ "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0] } ] },
                { "type": "sphere")",
     .mentions = {R"(a plane here is not a solid)", "a csg combines spheres"}},
    {.name = "CsgOfAnOpenCylinder",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "csg", "operation": "union", "objects": [
                  { "type": "sphere", "center": [0, 0, 0], "radius": 1 },
                  { "type": "csg", "operation": "intersection", "objects": [
                    { "type": "box", "min": [0, 0, 0], "max": [1, 1, 1] },
                    @{ "type": "cylinder", "base": [0, 0, 0], "top": [0, 1, 0], "radius": 1,
                      "open": true } ] } ] },
                { "type": "sphere")",
     .mentions = {R"(a cylinder here is not a solid)"}},
    {.name = "CsgChildWithAnUnknownKey",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "csg", "operation": "union", "objects": [
                  { "type": "sphere", "center": [0, 0, 0], "radius": 1 },
                  { "type": "sphere", "center": [0, 1, 0], @"radiuss": 1 } ] },
                { "type": "sphere")",
     .mentions = {R"("radiuss")", R"(did you mean "radius")"}},
    // --- groups (more in BadInputTest: those across included files) ---
    {.name = "UnknownGroup",
     .replace = R"("objects": [)",
     .with = R"("groups": { "tree": [] },
  "objects": [ { "type": "group", "group": @"tre" },)",
     .mentions = {R"(group "tre" is not defined)", R"(did you mean "tree"?)"}},
    {.name = "GroupWithoutItsName",
     .replace = R"("objects": [)",
     .with = R"("groups": { "tree": [] },
  "objects": [ @{ "type": "group", "transform": { "translate": [1, 0, 0] } },)",
     .mentions = {R"(a group needs "group")"}},
    {.name = "GroupPlacingItself",
     .replace = R"("objects": [)",
     .with = R"("groups": { "a": [ { "type": "group", "group": "b" } ],
              "b": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1 },
                     { "type": "group", "group": @"a" } ] },
  "objects": [)",
     .mentions = {R"(group cycle: "a" places "b" places "a")"}},
    {.name = "GroupNotAnArray",
     .replace = R"("objects": [)",
     .with = R"("groups": { "tree": @{ "type": "sphere" } },
  "objects": [)",
     .mentions = {R"(group "tree" must be an array)"}},
    {.name = "GroupInACsgIsNotASolid",
     .replace = R"("objects": [)",
     .with = R"("groups": { "pair": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1 },
                         { "type": "sphere", "center": [2, 0, 0], "radius": 1 } ] },
  "objects": [ { "type": "csg", "operation": "union", "objects": [
                 { "type": "sphere", "center": [0, 0, 0], "radius": 1 },
                 @{ "type": "group", "group": "pair" } ] },)",
     .mentions = {R"(a group here is not a solid)"}},
    {.name = "IncludeNotAnArray",
     .replace = R"("objects": [)",
     .with = R"("include": @"common.json",
  "objects": [)",
     .mentions = {R"("include" must be an array)"}},
    {.name = "CylinderOpenNotABoolean",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "cylinder", "base": [0, 0, 0], "top": [0, 1, 0], "radius": 1,
                  "open": @"yes" }, { "type": "sphere")",
     .mentions = {R"("open")"}},
    {.name = "DiskZeroNormal",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "disk", "center": [0, 0, 0], "normal": @[0, 0, 0], "radius": 1 },
                { "type": "sphere")",
     .mentions = {R"("normal" must be a non-zero direction)"}},
    {.name = "DiskWithoutRadius",
     .replace = R"({ "type": "sphere")",
     .with = R"(@{ "type": "disk", "center": [0, 0, 0], "normal": [0, 1, 0] }, { "type": "sphere")",
     .mentions = {R"(a disk needs "radius")"}},
    {.name = "NegativeRoughness",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "roughness": @-0.1)",
     .mentions = {R"("roughness")", "at least 0"}},
    {.name = "RoughnessAboveOne",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "roughness": @1.5)",
     .mentions = {R"("roughness" must be at most 1)"}},
    {.name = "RoughnessNotANumber",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "roughness": @"rough")",
     .mentions = {R"("roughness")", "number"}},
    {.name = "UnknownMetal",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "metal": @"gould")",
     .mentions = {R"("gould")", R"(did you mean "gold"?)",
                  R"("gold", "silver", "copper", "aluminium" or "chromium")"}},
    {.name = "MetalNotAString",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "metal": @1)",
     .mentions = {R"("metal")"}},
    {.name = "MetalAndConductorTogether",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "metal": "gold", "conductor": @{ "eta": 1, "k": 1 })",
     .mentions = {R"("metal" and "conductor" together)"}},
    {.name = "ConductorNotAnObject",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "conductor": @[1, 2, 3])",
     .mentions = {R"("conductor" must be an object)"}},
    {.name = "ConductorWithoutK",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "conductor": @{ "eta": 1 })",
     .mentions = {R"("k")"}},
    {.name = "ConductorUnknownKey",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "conductor": { "eta": 1, "k": 1, @"kappa": 2 })",
     .mentions = {R"(unknown key "kappa")", R"(expected "eta" or "k")"}},
    {.name = "ConductorEtaNotPositive",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "conductor": { "eta": @[1, 0, 1], "k": 1 })",
     .mentions = {R"("eta" must be greater than 0 in every channel)"}},
    {.name = "ConductorBadColour",
     .replace = R"("transmission": 1)",
     .with = R"("transmission": 1, "conductor": { "eta": 1, "k": @"red" })",
     .mentions = {R"("k")"}},
    {.name = "UnknownMaterialTypeListsTheValidOnes",
     .replace = R"("transmission": 1)",
     .with = R"("type": @"blinn-phong", "transmission": 1)",
     .mentions = {R"(unknown material type "blinn-phong")", R"(did you mean "blinn_phong"?)",
                  R"(expected "blinn_phong")"}},
    {.name = "UnknownObjectTypeListsTheValidOnes",
     .replace = R"("type": "sphere")",
     .with = R"("type": @"prism")",
     .mentions =
         {R"(unknown object type "prism")",
          R"(expected "sphere", "plane", "triangle", "mesh", "gltf", "disk", "box", "cylinder", "cone", "torus", "csg" or "group")"}},
    {.name = "UnknownLightTypeListsTheValidOnes",
     .replace = R"("type": "point")",
     .with = R"("type": @"area")",
     .mentions = {R"(unknown light type "area")",
                  R"(expected "point", "directional", "spot", "quad" or "sphere")"}},
    {.name = "UnknownKeyListsTheValidOnes",
     .replace = R"("radius": 1)",
     .with = R"("radius": 1, @"colour": 1)",
     .mentions =
         {R"(unknown key "colour" in a sphere; expected "type", "material", "transform", "name", "center" or "radius")"}},
    {.name = "UnknownTextureTypeListsTheValidOnes",
     .replace = R"({ "checker": {)",
     .with = R"({ @"chequer": {)",
     .mentions = {R"("chequer")", R"(did you mean "checker"?)",
                  R"(expected "texture" or "checker")"}},
    {.name = "MissingNormalMapFileIsNamed",
     .replace = R"("glass": { "diffuse": 0,)",
     .with = R"("glass": { "normal_map": @"bumps.png", "diffuse": 0,)",
     .mentions = {"normal map", "bumps.png"}},
    {.name = "MissingBumpMapFileIsNamed",
     .replace = R"("glass": { "diffuse": 0,)",
     .with = R"("glass": { "bump_map": @"heights.png", "diffuse": 0,)",
     .mentions = {"bump map", "heights.png"}},
    {.name = "NormalMapMustBeAFileName",
     .replace = R"("glass": { "diffuse": 0,)",
     .with = R"("glass": { "normal_map": @[0.5, 0.5, 1], "diffuse": 0,)",
     .mentions = {R"("normal_map" must be a string)"}},
    {.name = "BumpScaleMustBeANumber",
     .replace = R"("glass": { "diffuse": 0,)",
     .with = R"("glass": { "bump_map": "heights.png", "bump_scale": @"high", "diffuse": 0,)",
     .mentions = {R"("bump_scale" must be a number)"}},
    {.name = "BumpScaleWithoutBumpMap",
     .replace = R"("glass": { "diffuse": 0,)",
     .with = R"("glass": { @"bump_scale": 2, "diffuse": 0,)",
     .mentions = {R"("bump_scale")", R"("bump_map", which is missing)"}},
    {.name = "NormalMapAndBumpMapTogether",
     .replace = R"("glass": { "diffuse": 0,)",
     .with = R"("glass": { "normal_map": "n.png", @"bump_map": "h.png", "diffuse": 0,)",
     .mentions = {R"("normal_map" and "bump_map")", "give one of them"}},
    {.name = "MissingGltfFileIsNamed",
     .replace = R"({ "type": "plane",)",
     .with = R"({ "type": "gltf", "file": @"models/gone.glb" }, { "type": "plane",)",
     .mentions = {"glTF model", "gone.glb", "cannot open the glTF file"}},
    {.name = "UndefinedMaterialListsTheDefinedOnes",
     .replace = R"("material": "glass")",
     .with = R"("material": @"metal")",
     .mentions = {R"(material "metal" is not defined; expected "floor" or "glass")"}},
    {.name = "UnknownFilterListsTheValidOnes",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "filter": @"lanczos" })",
     .mentions = {R"(unknown filter "lanczos"; expected "box", "tent", "gaussian" or "mitchell")"}},
    {.name = "UnknownTonemapListsTheValidOnes",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "tonemap": @"reinhardt" })",
     .mentions =
         {R"(unknown tonemap "reinhardt" (did you mean "reinhard"?); expected "clamp", "reinhard" or "aces")"}},
    {.name = "TonemapNotAString",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "tonemap": @1 })",
     .mentions = {R"("tonemap" must be a string, got a number)"}},
    {.name = "ExposureNotANumber",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "exposure": @"+1" })",
     .mentions = {R"("exposure" must be a number)"}},
    {.name = "ExposureBeyondTheFloatRange",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "exposure": @-65 })",
     .mentions = {R"("exposure" must be between -64 and 64 stops)"}},
    {.name = "SmoothAbove180Degrees",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "mesh", "file": ")" + kTeapot + R"(", "smooth": @181 },
                { "type": "sphere")",
     .mentions = {R"("smooth" must be between 0 and 180 degrees)"}},
    {.name = "SmoothNegative",
     .replace = R"({ "type": "sphere")",
     .with = R"({ "type": "mesh", "file": ")" + kTeapot + R"(", "smooth": @-1 },
                { "type": "sphere")",
     .mentions = {R"("smooth")"}},
    {.name = "SampleClampZero",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "clamp": @0 })",
     .mentions = {R"("clamp")"}},
    {.name = "SampleClampNotANumber",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "clamp": @"high" })",
     .mentions = {R"("clamp")"}},
    {.name = "AdcBailoutNegative",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "adc_bailout": @-0.1 })",
     .mentions = {R"("adc_bailout" must be between 0 and 1)"}},
    {.name = "AdcBailoutAboveOne",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "adc_bailout": @1.5 })",
     .mentions = {R"("adc_bailout" must be between 0 and 1)"}},
    {.name = "AdcBailoutNotANumber",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "adc_bailout": @"1/255" })",
     .mentions = {R"("adc_bailout" must be a number)"}},
    {.name = "LightEdgeFactorZero",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "light_edge_factor": @0 })",
     .mentions = {R"("light_edge_factor")"}},
    {.name = "LightEdgeFactorNotAWholeNumber",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "light_edge_factor": @2.5 })",
     .mentions = {R"("light_edge_factor" must be a whole number)"}},
    {.name = "UnknownIntegratorInScene",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "integrator": @"whited" })",
     .mentions = {R"("whited")", R"(did you mean "whitted"?)"}},
    {.name = "EnvironmentMapMissing",
     .replace = R"("lights": [)",
     .with = R"("environment": { "file": @"no-such-sky.hdr" }, "lights": [)",
     .mentions = {R"(environment map)", "no-such-sky.hdr"}},
    {.name = "EnvironmentMapUnreadable",
     .replace = R"("lights": [)",
     .with = R"("environment": { "file": @"scene.json" }, "lights": [)",
     .mentions = {R"(environment map)", "scene.json"}},
    {.name = "EnvironmentAndBackgroundBoth",
     .replace = R"("lights": [)",
     .with = R"("background": 0.5, @"environment": { "file": "sky.hdr" }, "lights": [)",
     .mentions = {R"("environment" replaces "background")"}},
    {.name = "EnvironmentNegativeIntensity",
     .replace = R"("lights": [)",
     .with = R"("environment": { "file": ")" + kSky + R"(", "intensity": @-1 }, "lights": [)",
     .mentions = {R"("intensity")"}},
    {.name = "EnvironmentUnknownKey",
     .replace = R"("lights": [)",
     .with = R"("environment": { "file": "sky.hdr", @"intensty": 2 }, "lights": [)",
     .mentions = {R"(unknown key "intensty" in "environment")", R"(did you mean "intensity"?)",
                  R"(expected "file", "intensity", "rotate" or "samples")"}},
    {.name = "EnvironmentZeroSamples",
     .replace = R"("lights": [)",
     .with = R"("environment": { "file": ")" + kSky + R"(", "samples": @0 }, "lights": [)",
     .mentions = {R"("samples")"}},
    {.name = "EnvironmentNotAnObject",
     .replace = R"("lights": [)",
     .with = R"("environment": @"sky.hdr", "lights": [)",
     .mentions = {R"("environment")"}},
    {.name = "MissingRequiredKey",
     .replace = R"({ "type": "sphere", "center": [0, 1, 0], "radius": 1,)",
     .with = R"(@{ "type": "sphere", "center": [0, 1, 0],)",
     .mentions = {R"("radius")"}},
    {.name = "RadiusIsAString",
     .replace = R"("radius": 1)",
     .with = R"("radius": @"1")",
     .mentions = {R"("radius")", "number"}},
    {.name = "CenterHasTwoNumbers",
     .replace = R"("center": [0, 1, 0])",
     .with = R"("center": @[0, 1])",
     .mentions = {R"("center")"}},
    {.name = "WidthAboveTheLimit",
     .replace = R"("width": 8)",
     .with = R"("width": @32769)",
     .mentions = {R"("width" must be at most 32768)"}},
    {.name = "HeightFarAboveTheLimit",
     .replace = R"("height": 6)",
     .with = R"("height": @1000000000)",
     .mentions = {R"("height" must be at most 32768)"}},
    {.name = "SamplesFarAboveTheLimit",
     .replace = R"("spp": 1,)",
     .with = R"("spp": @1000000000,)",
     .mentions = {R"("spp" must be at most 1048576)"}},
    {.name = "AdaptiveMaxSamplesAboveTheLimit",
     .replace = R"("spp": 1,)",
     .with = R"("adaptive": { "max_spp": @1048577 },)",
     .mentions = {R"("max_spp" must be at most 1048576)"}},
    {.name = "AdaptiveMinSamplesAboveTheLimit",
     .replace = R"("spp": 1,)",
     .with = R"("adaptive": { "min_spp": @1048577 },)",
     .mentions = {R"("min_spp" must be at most 1048576)"}},
    {.name = "WidthIsNotWhole",
     .replace = R"("width": 8)",
     .with = R"("width": @8.5)",
     .mentions = {R"("width")"}},
    {.name = "ColourIsAString",
     .replace = R"("intensity": 40)",
     .with = R"("intensity": @"bright")",
     .mentions = {R"("intensity")"}},
    {.name = "LightsIsNotAnArray",
     .replace = R"([
    { "type": "point", "position": [2, 5, 3], "intensity": 40 }
  ])",
     .with = R"(@{ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .mentions = {R"("lights")"}},
    // --- bad values ---
    {.name = "NegativeRadius",
     .replace = R"("radius": 1)",
     .with = R"("radius": @-1)",
     .mentions = {R"("radius")"}},
    {.name = "ZeroNormal",
     .replace = R"("normal": [0, 1, 0])",
     .with = R"("normal": @[0, 0, 0])",
     .mentions = {R"("normal")"}},
    {.name = "SppZero", .replace = R"("spp": 1)", .with = R"("spp": @0)", .mentions = {R"("spp")"}},
    // --- the render block's sampling keys ---
    {.name = "UnknownFilter",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "filter": @"gausian" })",
     .mentions = {R"("gausian")", R"(did you mean "gaussian"?)"}},
    {.name = "UnknownFilterInObject",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "filter": { "type": @"mitchel" } })",
     .mentions = {R"("mitchel")", R"(did you mean "mitchell"?)"}},
    {.name = "FilterIsANumber",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "filter": @2 })",
     .mentions = {R"("filter")"}},
    {.name = "FilterWithoutType",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "filter": @{ "radius": 2 } })",
     .mentions = {R"("type")"}},
    {.name = "NegativeFilterRadius",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "filter": { "type": "tent", "radius": @-1 } })",
     .mentions = {R"("radius")"}},
    {.name = "HugeFilterRadius",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "filter": { "type": "box", "radius": @1000 } })",
     .mentions = {R"("radius")"}},
    {.name = "UnknownAdaptiveKey",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "adaptive": { @"treshold": 0.1 } })",
     .mentions = {R"("treshold")", R"(did you mean "threshold"?)"}},
    {.name = "MinSppAboveMaxSpp",
     .replace = R"("spp": 1, "max_depth": 3 })",
     .with = R"("max_depth": 3, "adaptive": { "min_spp": @64, "max_spp": 16 } })",
     .mentions = {R"("min_spp")", R"("max_spp")"}},
    {.name = "MinSppAboveSpp",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "adaptive": { "min_spp": @4 } })",
     .mentions = {R"("min_spp")", R"("spp")"}},
    {.name = "MaxSppBesideSpp",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "adaptive": { @"max_spp": 64 } })",
     .mentions = {R"("max_spp")", R"("spp")"}},
    {.name = "AdaptiveThresholdZero",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "adaptive": { "threshold": @0 } })",
     .mentions = {R"("threshold")"}},
    {.name = "AdaptiveThresholdNegative",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "adaptive": { "threshold": @-0.1 } })",
     .mentions = {R"("threshold")"}},
    {.name = "AdaptiveIsNotAnObject",
     .replace = R"("max_depth": 3 })",
     .with = R"("max_depth": 3, "adaptive": @true })",
     .mentions = {R"("adaptive")"}},
    {.name = "NegativeMaxDepth",
     .replace = R"("max_depth": 3)",
     .with = R"("max_depth": @-1)",
     .mentions = {R"("max_depth")"}},
    // Deeper recursion would overflow the stack (Whitted) or never end (path between mirrors).
    {.name = "MaxDepthAboveTheLimit",
     .replace = R"("max_depth": 3)",
     .with = R"("max_depth": @1025)",
     .mentions = {R"("max_depth" must be at most 1024)"}},
    {.name = "MaxDepthFarAboveTheLimit",
     .replace = R"("max_depth": 3)",
     .with = R"("max_depth": @1000000000)",
     .mentions = {R"("max_depth" must be at most 1024)"},
     .arguments = {"--integrator", "path"}},
    {.name = "NumberOutOfRange",
     .replace = R"("radius": 1)",
     .with = R"("radius": @1e999)",
     .mentions = {"number overflow parsing '1e999'"}},
    {.name = "NestedTooDeep",
     .replace = R"("objects": [)",
     .with = R"("objects": [)" + std::string(254, '[') + "@[",
     .mentions = {"nested more than 256 deep"}},
    {.name = "NegativeColour",
     .replace = R"("even": 0.9)",
     .with = R"("even": @-0.9)",
     .mentions = {R"("even")"}},
    {.name = "IorZero",
     .replace = R"("ior": 1.5)",
     .with = R"("ior": @0)",
     .mentions = {R"("ior")"}},
    {.name = "VfovOf180",
     .replace = R"("vfov": 40)",
     .with = R"("vfov": @180)",
     .mentions = {R"("vfov")"}},
    {.name = "UnknownCameraType",
     .replace = R"("vfov": 40)",
     .with = R"("type": @"fish_eye")",
     .mentions = {R"(unknown camera type "fish_eye")", R"(did you mean "fisheye"?)",
                  R"("perspective", "orthographic", "fisheye" or "latlong")"}},
    {.name = "KeyOfAnotherCameraType",
     .replace = R"("vfov": 40)",
     .with = R"("type": "fisheye", @"vfov": 40)",
     .mentions = {R"("vfov")", R"("fov")"}},
    {.name = "OrthographicWithAnAperture",
     .replace = R"("vfov": 40)",
     .with = R"("type": "orthographic", "height": 4, "aperture": @0.1)",
     .mentions = {R"("aperture")", "orthographic"}},
    {.name = "OrthographicWithoutHeight",
     .replace = R"("camera": { "position": [0, 1, 5], "look_at": [0, 0, 0], "vfov": 40 })",
     .with =
         R"("camera": @{ "type": "orthographic", "position": [0, 1, 5], "look_at": [0, 0, 0] })",
     .mentions = {R"("height")"}},
    {.name = "OrthographicHeightZero",
     .replace = R"("vfov": 40)",
     .with = R"("type": "orthographic", "height": @0)",
     .mentions = {R"("height")"}},
    {.name = "FisheyeFovAbove360",
     .replace = R"("vfov": 40)",
     .with = R"("type": "fisheye", "fov": @361)",
     .mentions = {R"("fov")", "360"}},
    {.name = "FisheyeFovZero",
     .replace = R"("vfov": 40)",
     .with = R"("type": "fisheye", "fov": @0)",
     .mentions = {R"("fov")"}},
    {.name = "LatLongWithAFieldOfView",
     .replace = R"("vfov": 40)",
     .with = R"("type": "latlong", @"vfov": 40)",
     .mentions = {R"("vfov")"}},
    {.name = "CameraTypeNotAString",
     .replace = R"("vfov": 40)",
     .with = R"("type": @3)",
     .mentions = {R"("type")"}},
    {.name = "CameraLooksAtItself",
     .replace = R"("look_at": [0, 0, 0])",
     .with = R"("look_at": @[0, 1, 5])",
     .mentions = {R"("look_at")"}},
    // --- area and spot lights (each replaces the point light) ---
    {.name = "QuadLightWithParallelEdges",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "quad", "corner": [0, 3, 0], "edge1": [1, 0, 0], "edge2": @[2, 0, 0], "radiance": 5 })",
     .mentions = {R"("edge2")", R"(no area)"}},
    {.name = "QuadLightWithAZeroEdge",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "quad", "corner": [0, 3, 0], "edge1": [0, 0, 0], "edge2": @[0, 0, 1], "radiance": 5 })",
     .mentions = {R"("edge1")", R"(no area)"}},
    {.name = "QuadLightNegativeRadiance",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "quad", "corner": [0, 3, 0], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "radiance": [1, @-1, 1] })",
     .mentions = {R"("radiance")"}},
    {.name = "QuadLightWithoutEdge2",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with = R"(@{ "type": "quad", "corner": [0, 3, 0], "edge1": [1, 0, 0], "radiance": 5 })",
     .mentions = {R"(quad light)", R"("edge2")"}},
    {.name = "QuadLightMisspeltKey",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "quad", "corner": [0, 3, 0], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "radiance": 5, @"sample": 4 })",
     .mentions = {R"("sample")", R"(did you mean "samples"?)"}},
    {.name = "QuadLightZeroSamples",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "quad", "corner": [0, 3, 0], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "radiance": 5, "samples": @0 })",
     .mentions = {R"("samples")"}},
    {.name = "QuadLightFractionalSamples",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "quad", "corner": [0, 3, 0], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "radiance": 5, "samples": @2.5 })",
     .mentions = {R"("samples")", R"(whole number)"}},
    {.name = "SphereLightZeroRadius",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with = R"({ "type": "sphere", "center": [0, 3, 0], "radius": @0, "radiance": 5 })",
     .mentions = {R"("radius")"}},
    {.name = "SphereLightWithoutRadiance",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with = R"(@{ "type": "sphere", "center": [0, 3, 0], "radius": 1 })",
     .mentions = {R"(sphere light)", R"("radiance")"}},
    {.name = "SphereLightWithIntensity",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with = R"({ "type": "sphere", "center": [0, 3, 0], "radius": 1, @"intensity": 5 })",
     .mentions = {R"("intensity")", R"(sphere light)"}},
    {.name = "SpotLightConeAngleAbove180",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "intensity": 5, "cone_angle": @190 })",
     .mentions = {R"("cone_angle")", R"(180)"}},
    {.name = "SpotLightConeAngleZero",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "intensity": 5, "cone_angle": @0 })",
     .mentions = {R"("cone_angle")"}},
    {.name = "SpotLightFalloffWiderThanCone",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "intensity": 5, "cone_angle": 20, "cone_falloff": @30 })",
     .mentions = {R"("cone_falloff")", R"("cone_angle")"}},
    {.name = "SpotLightNegativeFalloff",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "intensity": 5, "cone_falloff": @-1 })",
     .mentions = {R"("cone_falloff")"}},
    {.name = "SpotLightDirectionAndLookAt",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "look_at": @[0, 0, 0], "intensity": 5 })",
     .mentions = {R"("direction")", R"("look_at")", R"(not both)"}},
    {.name = "SpotLightWithoutDirection",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with = R"(@{ "type": "spot", "position": [0, 3, 0], "intensity": 5 })",
     .mentions = {R"("direction")", R"("look_at")"}},
    {.name = "SpotLightLooksAtItself",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with = R"({ "type": "spot", "position": [0, 3, 0], "look_at": @[0, 3, 0], "intensity": 5 })",
     .mentions = {R"("look_at")"}},
    {.name = "SpotLightZeroDirection",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "spot", "position": [0, 3, 0], "direction": @[0, 0, 0], "intensity": 5 })",
     .mentions = {R"("direction")"}},
    {.name = "SpotLightUnknownFalloff",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "intensity": 5, "falloff": @"nnone" })",
     .mentions = {R"("nnone")", R"(did you mean "none"?)"}},
    {.name = "SpotLightMisspeltConeAngle",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with =
         R"({ "type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "intensity": 5, @"cone_angel": 20 })",
     .mentions = {R"("cone_angel")", R"(did you mean "cone_angle"?)"}},
    {.name = "MisspeltSpotType",
     .replace = R"({ "type": "point", "position": [2, 5, 3], "intensity": 40 })",
     .with = R"({ "type": @"spto", "position": [0, 3, 0], "intensity": 5 })",
     .mentions = {R"("spto")", R"(did you mean "spot"?)"}},
    // --- the files ---
    {.name = "MissingSceneFile",
     .prefix = "scene.json: error: ",
     .mentions = {"scene.json"},
     .writeScene = false},
    // --- options ---
    {.name = "MisspeltIntegratorOptionListsTheValidOnes",
     .prefix = "lancer: error: ",
     .mentions =
         {R"(unknown integrator "whited" (did you mean "whitted"?); expected "whitted", "path" or "radiosity")"},
     .arguments = {"--integrator", "whited"}},
    {.name = "MisspeltOptionSuggestsAndListsTheValidOnes",
     .prefix = "lancer: error: ",
     .mentions =
         {R"(unknown option "--sample" (did you mean "--spp"?); expected "--help", "--version", "--output")",
          R"("--save-radiosity", "--load-radiosity", "--model-cache", "--no-model-cache" or "--max-memory")"},
     .arguments = {"--sample", "4"}},
    {.name = "MisspeltAovListsTheValidOnes",
     .prefix = "lancer: error: ",
     .mentions =
         {R"(--aov "normal,albdo": unknown output "albdo" (did you mean "albedo"?); expected "albedo", "normal" or "depth")"},
     .arguments = {"--aov", "normal,albdo"}},
    {.name = "EmptyAovList",
     .prefix = "lancer: error: ",
     .mentions = {R"(--aov "": an empty name)", R"("albedo", "normal" or "depth")"},
     .arguments = {"--aov", ""}},
    {.name = "AovListEndingInAComma",
     .prefix = "lancer: error: ",
     .mentions = {R"(--aov "depth,": an empty name)"},
     .arguments = {"--aov", "depth,"}},
    {.name = "AovNamedTwice",
     .prefix = "lancer: error: ",
     .mentions = {R"(--aov "depth,normal,depth": "depth" is named twice)"},
     .arguments = {"--aov", "depth,normal,depth"}},
    {.name = "NegativeSeed",
     .prefix = "lancer: error: ",
     .mentions = {"--seed", "-3", ">= 0"},
     .arguments = {"--seed", "-3"}},
    {.name = "SppNotANumber",
     .prefix = "lancer: error: ",
     .mentions = {"--spp", "abc"},
     .arguments = {"--spp", "abc"}},
    {.name = "SppZeroOption",
     .prefix = "lancer: error: ",
     .mentions = {"--spp"},
     .arguments = {"--spp", "0"}},
    {.name = "WidthZeroOption",
     .prefix = "lancer: error: ",
     .mentions = {"--width"},
     .arguments = {"--width", "0"}},
    {.name = "CropMalformed",
     .prefix = "lancer: error: ",
     .mentions = {"--crop", "1,2,3"},
     .arguments = {"--crop", "1,2,3"}},
    {.name = "CropNotNumbers",
     .prefix = "lancer: error: ",
     .mentions = {"--crop"},
     .arguments = {"--crop", "a,b,c,d"}},
    {.name = "CropOutsideTheImage",
     .prefix = "lancer: error: ",
     .mentions = {"--crop"},
     .arguments = {"--crop", "0,0,9,6"}},
    {.name = "CropEmpty",
     .prefix = "lancer: error: ",
     .mentions = {"--crop"},
     .arguments = {"--crop", "4,2,4,5"}},
    {.name = "UnknownOption",
     .prefix = "lancer: error: ",
     .mentions = {"--fast"},
     .arguments = {"--fast"}},
    {.name = "UnknownIntegratorOption",
     .prefix = "lancer: error: ",
     .mentions = {"--integrator", "photon"},
     .arguments = {"--integrator", "photon"}},
    {.name = "MisspeltOutputExtension",
     .prefix = "lancer: error: ",
     .mentions =
         {R"(unknown output format ".pgn" for out.pgn (did you mean ".png"?) (expected one of .png, )"},
     .arguments = kHugeRender,
     .output = "out.pgn"},
    {.name = "HeightOptionAboveTheLimit",
     .prefix = "lancer: error: ",
     .mentions = {"--height", "32768"},
     .arguments = {"--height", "32769"}},
    {.name = "MaxMemoryWithoutANumber",
     .prefix = "lancer: error: ",
     .mentions = {"--max-memory", R"(expected a size such as 500M, 64G or 2T, got "lots")"},
     .arguments = {"--max-memory", "lots"}},
    {.name = "MaxMemoryWithAnUnknownUnit",
     .prefix = "lancer: error: ",
     .mentions = {"--max-memory", R"(got "8GiB")"},
     .arguments = {"--max-memory", "8GiB"}},
    {.name = "MaxMemoryOfZero",
     .prefix = "lancer: error: ",
     .mentions = {"--max-memory", R"(got "0")"},
     .arguments = {"--max-memory", "0"}},
    {.name = "MaxMemoryNegative",
     .prefix = "lancer: error: ",
     .mentions = {"--max-memory", R"(got "-1G")"},
     .arguments = {"--max-memory=-1G"}},
    {.name = "MaxMemoryBeyondWhatCounts",
     .prefix = "lancer: error: ",
     .mentions = {"--max-memory", R"(got "99999999T")"},
     .arguments = {"--max-memory", "99999999T"}},
    {.name = "AdcBailoutOptionAboveOne",
     .prefix = "lancer: error: ",
     .mentions = {"--adc-bailout"},
     .arguments = {"--adc-bailout", "2"}},
    {.name = "LightEdgeFactorOptionZero",
     .prefix = "lancer: error: ",
     .mentions = {"--light-edge-factor"},
     .arguments = {"--light-edge-factor", "0"}},
    {.name = "MaxDepthOptionAboveTheLimit",
     .prefix = "lancer: error: ",
     .mentions = {"--max-depth", "1024"},
     .arguments = {"--max-depth", "1025"}},
    {.name = "UnknownOutputExtension",
     .prefix = "lancer: error: ",
     .mentions = {"out.xyz", ".png"},
     .arguments = kHugeRender,
     .output = "out.xyz"},
    // --- failures that are not bad input: exit 1 ---
    {.name = "OutputFolderMissing",
     .prefix = "lancer: error: ",
     .mentions = {"nowhere/out.png"},
     .arguments = kHugeRender,
     .exitStatus = kFailure,
     .output = "nowhere/out.png"},
    {.name = "OutputIsAFolder",
     .prefix = "lancer: error: ",
     .mentions = {"out.png", "is a folder"},
     .exitStatus = kFailure,
     .outputIsAFolder = true},
};

INSTANTIATE_TEST_SUITE_P(Cases, CliError, testing::ValuesIn(kErrorCases), CaseName());

std::vector<ErrorCase> casesWithAPossibleOutputFile() {
    std::vector<ErrorCase> cases;
    for (const ErrorCase& c : kErrorCases)
        if (!c.outputIsAFolder && c.output.find('/') == std::string::npos) cases.push_back(c);
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Cases, CliErrorWithPreexistingOutput,
                         testing::ValuesIn(casesWithAPossibleOutputFile()), CaseName());

}  // namespace
}  // namespace lancer::test
