// The documentation against the files it describes: every example scene of docs/SCENE-FORMAT.md
// is a file of scenes/ that renders with each of its objects in sight, and scenes/models/SOURCES.md
// lists the models' files as they are.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "LancerRun.h"

namespace lancer::test {
namespace {

const fs::path kSource = LANCER_SOURCE_DIR;

// An example of the documentation: the text of a ```jsonc block and the scenes/ file the
// paragraph before it names.
struct Example {
    std::string text;
    std::string file;  // "scenes/NAME.json", or "" when the paragraph names none
};

std::vector<Example> examplesOf(const std::string& documentation) {
    std::vector<Example> examples;
    const std::string fence = "```jsonc\n";
    for (std::size_t at = documentation.find(fence); at != std::string::npos;
         at = documentation.find(fence, at + 1)) {
        const std::size_t start = at + fence.size();
        const std::size_t end = documentation.find("```\n", start);
        // The paragraph before the blank line that precedes the block.
        const std::size_t paragraph = documentation.rfind("\n\n", at - 3);
        const std::size_t named = documentation.find("`scenes/", paragraph);
        Example example{documentation.substr(start, end - start), ""};
        if (named < at)
            example.file =
                documentation.substr(named + 1, documentation.find('`', named + 1) - named - 1);
        examples.push_back(example);
    }
    return examples;
}

TEST(Documentation, EveryExampleSceneIsAFileOfScenes) {
    const std::vector<Example> examples = examplesOf(readFile(kSource / "docs/SCENE-FORMAT.md"));
    ASSERT_FALSE(examples.empty());
    for (const Example& example : examples) {
        ASSERT_NE(example.file, "") << "an example names no file of scenes/:\n" << example.text;
        EXPECT_EQ(readFile(kSource / example.file), example.text) << example.file;
    }
}

// Each object of the example scene `name` of scenes/, taken out, changes the picture: none hides
// behind another.
void expectEveryObjectInSight(const std::string& name) {
    const fs::path file = kSource / "scenes" / name;
    const std::vector<std::string> small{"--width", "96", "--height", "72", "--spp", "1"};
    nlohmann::json scene = nlohmann::json::parse(readFile(file), nullptr, true, true);
    // The copies are written elsewhere: the paths of models and includes are made absolute.
    const auto absolute = [](nlohmann::json& path) {
        path = (kSource / "scenes" / path.get<std::string>()).string();
    };
    for (nlohmann::json& object : scene["objects"])
        if (object.contains("file")) absolute(object["file"]);
    if (scene.contains("include"))
        for (nlohmann::json& path : scene["include"])
            absolute(path);
    const Image whole = renderSceneFile(file, small).image;
    EXPECT_EQ(renderScene(scene, small).image.pixels, whole.pixels);
    for (std::size_t i = 0; i < scene["objects"].size(); ++i) {
        nlohmann::json without = scene;
        without["objects"].erase(i);
        const Image image = renderScene(without, small).image;
        // At least a few pixels change clearly (the format example's smallest object is the lamp).
        const double unchanged = fractionOfPixelsWithin(image, whole, 0.05, 0);
        EXPECT_LT(unchanged, 1 - 4.0 / (96 * 72)) << scene["objects"][i].dump();
    }
}

TEST(Documentation, TheFormatExampleRendersWithEveryObjectInSight) {
    expectEveryObjectInSight("format-example.json");
}

TEST(Documentation, TheIncludeAndGroupExampleRendersWithEveryObjectInSight) {
    expectEveryObjectInSight("grove.json");
}

// The sections of scenes/models/SOURCES.md, "## N. `folder/`: ...", with their text.
struct Section {
    int number;
    std::string folder;
    std::string text;
};

std::vector<Section> sectionsOf(const std::string& sources) {
    std::vector<Section> sections;
    for (std::size_t at = sources.find("\n## "); at != std::string::npos;) {
        const std::size_t next = sources.find("\n## ", at + 1);
        const std::string text = sources.substr(at + 4, next - at - 4);
        const std::size_t open = text.find('`'), close = text.find("/`");
        sections.push_back({std::atoi(text.c_str()),
                            open < close ? text.substr(open + 1, close - open - 1) : "", text});
        at = next;
    }
    return sections;
}

TEST(Documentation, ModelSourcesAreNumberedAndListTheFilesThatAreThere) {
    const fs::path models = kSource / "scenes/models";
    const std::vector<Section> sections = sectionsOf(readFile(models / "SOURCES.md"));
    ASSERT_FALSE(sections.empty());
    std::vector<std::string> described;
    for (std::size_t i = 0; i < sections.size(); ++i) {
        const Section& section = sections[i];
        EXPECT_EQ(section.number, static_cast<int>(i) + 1) << section.text.substr(0, 60);
        ASSERT_TRUE(fs::is_directory(models / section.folder)) << section.folder;
        described.push_back(section.folder);
        // The files of its tables (the first cell of a row) are there.
        for (std::size_t row = section.text.find("\n| "); row != std::string::npos;
             row = section.text.find("\n| ", row + 1)) {
            const std::string cell =
                section.text.substr(row + 3, section.text.find_first_of(" |", row + 3) - row - 3);
            if (cell == "file" || cell.find('.') == std::string::npos) continue;
            EXPECT_TRUE(fs::exists(models / section.folder / cell)) << section.folder << cell;
        }
        // And every file of the folder is described (by its name, or its stem: "X.obj (+.mtl)").
        for (const fs::directory_entry& entry : fs::directory_iterator(models / section.folder)) {
            const fs::path name = entry.path().filename();
            EXPECT_TRUE(section.text.find(name.string()) != std::string::npos ||
                        section.text.find(name.stem().string()) != std::string::npos)
                << section.folder << "/" << name.string() << " is not in SOURCES.md";
        }
    }
    for (const fs::directory_entry& entry : fs::directory_iterator(models)) {
        if (!entry.is_directory()) continue;
        const std::string folder = entry.path().filename().string();
        EXPECT_NE(std::find(described.begin(), described.end(), folder), described.end())
            << folder << " has no section in SOURCES.md";
    }
}

}  // namespace
}  // namespace lancer::test
