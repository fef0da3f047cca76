// glTF models end to end: the sample model written as OBJ, .gltf and .glb renders the same image;
// a scene material overrides the model's; metallic-roughness renders as the scene's conductor and
// roughness; what lancer cannot show is a warning and the render goes on; a malformed file is one
// error line and exit status 2.

#include <gtest/gtest.h>

#include "LancerRun.h"

namespace lancer::test {
namespace {

using json = nlohmann::json;

const fs::path kSpot = fs::path(LANCER_SOURCE_DIR) / "scenes/models/spot";

// Spot under a point light, placed by a transform, as a "mesh" (OBJ) or a "gltf" object.
json spotScene(const json& object) {
    json placed = object;
    placed["transform"] = {{"scale", 1.5}, {"rotate", {0, 1, 0, 40}}, {"translate", {0, 0.2, 0}}};
    return {{"render", {{"width", 48}, {"height", 40}, {"spp", 2}, {"max_depth", 2}}},
            {"camera", {{"position", {2, 1.2, 3}}, {"look_at", {0, 0.2, 0}}}},
            {"materials", {{"red", {{"diffuse", {0.7, 0.1, 0.1}}, {"specular", 0.3}}}}},
            {"objects", {placed}},
            {"lights", {{{"type", "point"}, {"position", {3, 4, 5}}, {"intensity", 40}}}}};
}

json objSpot() {
    return {{"type", "mesh"}, {"file", (kSpot / "spot_textured.obj").string()}};
}

json gltfSpot(const std::string& file) {
    return {{"type", "gltf"}, {"file", (kSpot / file).string()}};
}

// The glTF holds the OBJ's positions bit for bit and its uvs as 1 - v, which turned back is v to
// within an ulp of 1 (6e-8): texture lookups move by that much, far below the bound.
constexpr double kSameImage = 1e-5;

TEST(CliGltf, GltfAndGlbRenderAsTheObjTheyWereMadeFrom) {
    const Image obj = renderScene(spotScene(objSpot())).image;
    for (const char* file : {"spot.gltf", "spot.glb"}) {
        const Image gltf = renderScene(spotScene(gltfSpot(file))).image;
        EXPECT_LE(maxAbsoluteDifference(gltf, obj), kSameImage) << file;
    }
}

TEST(CliGltf, SceneMaterialOverridesTheModels) {
    json obj = objSpot(), gltf = gltfSpot("spot.glb");
    const Image textured = renderScene(spotScene(gltf)).image;
    obj["material"] = gltf["material"] = "red";
    const Image red = renderScene(spotScene(gltf)).image;
    EXPECT_LE(maxAbsoluteDifference(red, renderScene(spotScene(obj)).image), kSameImage);
    EXPECT_GT(maxAbsoluteDifference(red, textured), 0.1);
}

// Spot's .gltf copied into `folder` with its material's pbrMetallicRoughness replaced, as a
// "gltf" object.
json spotWithPbr(const TempFolder& folder, const json& pbr) {
    for (const char* file : {"spot.bin", "spot_texture.png"})
        fs::copy_file(kSpot / file, folder / file);
    json model = json::parse(readFile(kSpot / "spot.gltf"));
    model["materials"][0]["pbrMetallicRoughness"] = pbr;
    folder.write("spot.gltf", model.dump());
    return {{"type", "gltf"}, {"file", (folder / "spot.gltf").string()}};
}

// Spot under a sky of one colour above a grey floor, for a mirror to show something.
json spotUnderSky(const json& object) {
    json scene = spotScene(object);
    scene["background"] = {0.55, 0.7, 0.9};
    scene["objects"].push_back({{"type", "plane"}, {"point", {0, -0.5, 0}}, {"normal", {0, 1, 0}}});
    return scene;
}

// The same with Spot's OBJ made of a scene material.
json objSpotUnderSky(const json& material) {
    json object = objSpot();
    object["material"] = "model";
    json scene = spotUnderSky(object);
    scene["materials"]["model"] = material;
    return scene;
}

// The base colour (0.8, 0.5, 0.2) is the head-on reflectance of eta = 1, k = 2 sqrt(F0 / (1 - F0))
// = (4, 2, 1): a metallic glTF renders as that scene conductor, roughnessFactor r as the scene's
// roughness r^2. The k of the glTF's factors are (4, 2, 1) within float rounding (1e-7), which
// moves the Fresnel term by less than kSameImage.
TEST(CliGltf, MetallicRendersAsTheSceneConductorAndRoughnessIsSquared) {
    const json conductor = {{"eta", 1}, {"k", {4, 2, 1}}};
    for (const float roughness : {0.0f, 0.5f}) {
        const TempFolder folder;
        const json gltf = spotWithPbr(folder, {{"baseColorFactor", {0.8, 0.5, 0.2, 1}},
                                               {"metallicFactor", 1},
                                               {"roughnessFactor", roughness}});
        const Image fromGltf = renderScene(spotUnderSky(gltf)).image;
        const Image fromScene = renderScene(objSpotUnderSky({{"conductor", conductor},
                                                             {"roughness", roughness * roughness}}))
                                    .image;
        EXPECT_LE(maxAbsoluteDifference(fromGltf, fromScene), kSameImage) << roughness;
        // Not the same image for any material: a diffuse Spot differs.
        const Image diffuse = renderScene(objSpotUnderSky({{"diffuse", 0.8}})).image;
        EXPECT_GT(maxAbsoluteDifference(fromGltf, diffuse), 0.1) << roughness;
    }
}

// A dielectric (metallic 0) is its base colour as a diffuse material, whatever its roughness.
TEST(CliGltf, DielectricRendersAsTheDiffuseBaseColour) {
    const TempFolder folder;
    const json gltf = spotWithPbr(
        folder,
        {{"baseColorFactor", {0.8, 0.5, 0.2, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.5}});
    const Image diffuse = renderScene(objSpotUnderSky({{"diffuse", {0.8, 0.5, 0.2}}})).image;
    EXPECT_LE(maxAbsoluteDifference(renderScene(spotUnderSky(gltf)).image, diffuse), kSameImage);
}

TEST(CliGltf, UnsupportedFeaturesWarnAndTheRenderGoesOn) {
    const TempFolder folder;
    fs::copy_file(kSpot / "spot.bin", folder / "spot.bin");
    fs::copy_file(kSpot / "spot_texture.png", folder / "spot_texture.png");
    json model = json::parse(readFile(kSpot / "spot.gltf"));
    model["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
    model["extensionsUsed"] = {"KHR_lights_punctual"};
    model["extensions"] = {
        {"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 5}}}}}}};
    folder.write("spot.gltf", model.dump());
    json scene = spotScene({{"type", "gltf"}, {"file", "spot.gltf"}});
    folder.write("scene.json", scene.dump());
    // Without --quiet, which silences warnings too.
    const RunResult run = runLancer({"scene.json", "-o", "out.pfm"}, folder.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    std::vector<std::string> lines;
    for (const std::string& line : run.errorLines())
        if (line.find(": warning: ") != std::string::npos) lines.push_back(line);
    ASSERT_EQ(lines.size(), 2u) << run;
    EXPECT_NE(lines[0].find("spot.gltf: warning: the file's cameras are not used"),
              std::string::npos)
        << lines[0];
    EXPECT_NE(lines[1].find("spot.gltf: warning: the file's lights (KHR_lights_punctual)"),
              std::string::npos)
        << lines[1];
    EXPECT_TRUE(fs::exists(folder / "out.pfm"));
}

TEST(CliGltf, MalformedFileIsOneErrorLine) {
    const TempFolder folder;
    folder.write("broken.glb", std::string("glTF\x02\0\0\0 truncated", 18));
    folder.write("scene.json", spotScene({{"type", "gltf"}, {"file", "broken.glb"}}).dump());
    const RunResult run = runLancer({"scene.json", "-o", "out.png", "--quiet"}, folder.path());
    EXPECT_EQ(run.exitStatus, 2) << run;
    ASSERT_EQ(run.errorLines().size(), 1u) << run;
    EXPECT_NE(run.errorLines()[0].find("glTF model"), std::string::npos) << run;
    EXPECT_NE(run.errorLines()[0].find("broken.glb"), std::string::npos) << run;
    EXPECT_FALSE(fs::exists(folder / "out.png"));
}

}  // namespace
}  // namespace lancer::test
