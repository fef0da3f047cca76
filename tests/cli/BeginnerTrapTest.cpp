// Beginner traps (docs/SCENE-FORMAT.md, "Warnings"): one warning line each on stderr, and the
// render goes on (exit status 0).

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace lancer::test
