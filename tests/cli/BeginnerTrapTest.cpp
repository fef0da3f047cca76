// Beginner traps (docs/SCENE-FORMAT.md, "Warnings"): one warning line each on stderr, and the
// render goes on (exit status 0).

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>

#include "LancerRun.h"

namespace lancer::test {
namespace {

// The warning lines of a run of `scene` (without --quiet, which silences warnings too).
std::vector<std::string> warningsOf(const nlohmann::json& scene) {
    const TempFolder folder;
    folder.write("scene.json", scene.dump(2));
    const RunResult run = runLancer({"scene.json", "-o", "out.pfm"}, folder.path());
    EXPECT_EQ(run.exitStatus, 0) << run;
    std::vector<std::string> lines;
    for (const std::string& line : run.errorLines())
        if (line.find(": warning: ") != std::string::npos) lines.push_back(line);
    return lines;
}

nlohmann::json sphereScene(const nlohmann::json& material) {
    nlohmann::json scene = nlohmann::json::parse(R"({
      "render": { "width": 4, "height": 3, "spp": 1 },
      "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] },
      "objects": [ { "type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m" } ],
      "lights": [ { "type": "point", "position": [2, 5, 3], "intensity": 40 } ]
    })");
    scene["materials"]["m"] = material;
    return scene;
}

TEST(CliBeginnerTrap, ReflectancesWrittenAs8BitValuesWarnOncePerKey) {
    const std::vector<std::string> lines =
        warningsOf(sphereScene({{"diffuse", {255, 128, 0}}, {"specular", 200}}));
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_NE(lines[0].find(R"(warning: "diffuse" [255,128,0] looks like 8-bit values)"),
              std::string::npos)
        << lines[0];
    EXPECT_NE(lines[1].find(R"(warning: "specular" 200 looks like 8-bit values)"),
              std::string::npos)
        << lines[1];
}

TEST(CliBeginnerTrap, ColoursThatAreNotBytesDoNotWarn) {
    // Within [0, 1]; above 1 but fractional; emission, whose radiance is often large and whole.
    for (const nlohmann::json& material :
         {nlohmann::json{{"diffuse", {1, 0, 1}}}, nlohmann::json{{"diffuse", {1.5, 2, 0}}},
          nlohmann::json{{"diffuse", 0.5}, {"emission", {255, 100, 20}}},
          nlohmann::json{{"diffuse", 0}, {"transmission", 1}, {"ior", 1.5}}})
        EXPECT_TRUE(warningsOf(sphereScene(material)).empty()) << material;
}

// An open box (floor and three walls, as high as the light) with a sphere in it, under a quad
// light shining down through its open top, or up when its edges are swapped.
nlohmann::json openBoxScene(bool swapEdges) {
    nlohmann::json scene = nlohmann::json::parse(R"({
      "render": { "width": 4, "height": 3, "spp": 1 },
      "camera": { "position": [0, 1, 5], "look_at": [0, 1, 0] },
      "objects": [
        { "type": "box", "min": [-1, -0.1, -1], "max": [1, 0, 1] },
        { "type": "box", "min": [-1, 0, -1.1], "max": [1, 2, -1] },
        { "type": "box", "min": [-1.1, 0, -1], "max": [-1, 2, 1] },
        { "type": "box", "min": [1, 0, -1], "max": [1.1, 2, 1] },
        { "type": "sphere", "center": [0, 0.5, 0], "radius": 0.5 } ],
      "lights": [ { "type": "quad", "corner": [-0.5, 2, -0.5], "edge1": [1, 0, 0],
                    "edge2": [0, 0, 1], "radiance": 3 } ]
    })");
    if (swapEdges) std::swap(scene["lights"][0]["edge1"], scene["lights"][0]["edge2"]);
    return scene;
}

// Where the warnings of `scene` name its first light: the line and column of its '{', as
// warningsOf writes the scene.
std::string placeOfFirstLight(const nlohmann::json& scene) {
    const std::string text = scene.dump(2);
    const std::size_t lights = text.find("\"lights\"");
    const std::size_t brace = text.find('{', lights);
    const std::size_t lineStart = text.rfind('\n', brace) + 1;
    const auto line = std::count(text.begin(), text.begin() + static_cast<long>(brace), '\n') + 1;
    return "scene.json:" + std::to_string(line) + ":" + std::to_string(brace - lineStart + 1) +
           ": warning: ";
}

TEST(CliBeginnerTrap, QuadLightFacingAwayFromEverySurfaceWarnsOnceAtTheLight) {
    const nlohmann::json scene = openBoxScene(true);
    const std::vector<std::string> lines = warningsOf(scene);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].rfind(placeOfFirstLight(scene), 0), 0u) << lines[0];
    EXPECT_NE(lines[0].find("the quad light faces away from every surface of the scene"),
              std::string::npos)
        << lines[0];
}

TEST(CliBeginnerTrap, QuadLightWithASurfaceOnItsLitSideDoesNotWarn) {
    // Shining into the box; shining up at a ceiling; shining up beside an infinite floor, which
    // reaches every side of the light (planes are not looked into); alone in the scene.
    nlohmann::json ceiling = openBoxScene(true);
    ceiling["objects"].push_back(
        nlohmann::json::parse(R"({ "type": "box", "min": [-1, 2.5, -1], "max": [1, 2.6, 1] })"));
    nlohmann::json floor = openBoxScene(true);
    floor["objects"].push_back(
        nlohmann::json::parse(R"({ "type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0] })"));
    nlohmann::json alone = openBoxScene(true);
    alone.erase("objects");
    for (const nlohmann::json& scene : {openBoxScene(false), ceiling, floor, alone})
        EXPECT_TRUE(warningsOf(scene).empty()) << scene["objects"].dump();
}

}  // namespace
}  // namespace lancer::test
