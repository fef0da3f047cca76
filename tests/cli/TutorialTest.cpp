// The tutorial against its scenes: docs/TUTORIAL.md names every scene of scenes/tutorial and only
// those, each renders without a warning, and the pictures say what the text says they show.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "LancerRun.h"

namespace lancer::test {
namespace {

const fs::path kSource = LANCER_SOURCE_DIR;
const fs::path kTutorial = kSource / "scenes/tutorial";

// The names NAME.json of the files of scenes/tutorial.
std::set<std::string> scenesOfTheFolder() {
    std::set<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(kTutorial))
        if (entry.path().extension() == ".json") names.insert(entry.path().filename().string());
    return names;
}

// The name that starts at `start` in `text`: a path's last part (letters, digits, '.', '-', '_'),
// without a sentence's full stop.
std::string nameAt(const std::string& text, std::size_t start) {
    std::size_t end = start;
    while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) ||
                                 text[end] == '.' || text[end] == '-' || text[end] == '_'))
        ++end;
    std::string name = text.substr(start, end - start);
    while (!name.empty() && name.back() == '.')
        name.pop_back();
    return name;
}

// The names that follow `prefix` in `text`.
std::set<std::string> namesAfter(const std::string& text, const std::string& prefix) {
    std::set<std::string> names;
    for (std::size_t at = text.find(prefix); at != std::string::npos;
         at = text.find(prefix, at + 1)) {
        const std::string name = nameAt(text, at + prefix.size());
        if (!name.empty()) names.insert(name);
    }
    return names;
}

std::string tutorialText() {
    return readFile(kSource / "docs/TUTORIAL.md");
}

TEST(Tutorial, EverySceneItNamesIsAFileOfScenesTutorial) {
    const std::set<std::string> named = namesAfter(tutorialText(), "scenes/tutorial/");
    ASSERT_GE(named.size(), 8u);
    for (const std::string& name : named)
        EXPECT_TRUE(fs::is_regular_file(kTutorial / name)) << "scenes/tutorial/" << name;
}

TEST(Tutorial, EverySceneOfScenesTutorialIsInTheTutorialWithItsPicture) {
    const std::string text = tutorialText();
    const std::set<std::string> named = namesAfter(text, "scenes/tutorial/");
    const std::set<std::string> pictures = namesAfter(text, "tutorial/");
    for (const std::string& name : scenesOfTheFolder()) {
        EXPECT_TRUE(named.count(name)) << "scenes/tutorial/" << name << " is not in the tutorial";
        const std::string picture = fs::path(name).replace_extension(".png").string();
        EXPECT_TRUE(pictures.count(picture)) << "the tutorial shows no tutorial/" << picture;
        EXPECT_TRUE(fs::is_regular_file(kSource / "docs/tutorial" / picture)) << picture;
    }
}

// The sections of the tutorial ("## "), each with the scenes/tutorial file it names first.
struct Step {
    std::string scene;  // "" when the section names none
    std::string text;
};

std::vector<Step> stepsOf(const std::string& tutorial) {
    const std::string prefix = "scenes/tutorial/";
    std::vector<Step> steps;
    for (std::size_t at = tutorial.find("\n## "); at != std::string::npos;) {
        const std::size_t next = tutorial.find("\n## ", at + 1);
        const std::string text = tutorial.substr(at + 1, next - at - 1);
        const std::size_t named = text.find(prefix);
        steps.push_back(
            {named == std::string::npos ? "" : nameAt(text, named + prefix.size()), text});
        at = next;
    }
    return steps;
}

std::string trimmed(const std::string& line) {
    const std::size_t start = line.find_first_not_of(' ');
    return start == std::string::npos ? ""
                                      : line.substr(start, line.find_last_not_of(' ') + 1 - start);
}

// The ```jsonc blocks of a step quote its scene: each of their lines is a line of the file.
TEST(Tutorial, EveryExcerptIsInTheSceneOfItsStep) {
    int blocks = 0;
    for (const Step& step : stepsOf(tutorialText())) {
        const std::string fence = "```jsonc\n";
        for (std::size_t at = step.text.find(fence); at != std::string::npos;
             at = step.text.find(fence, at + 1)) {
            ASSERT_NE(step.scene, "") << "a section with an excerpt names no scene:\n"
                                      << step.text.substr(0, 80);
            ++blocks;
            std::set<std::string> lines;
            std::istringstream file(readFile(kTutorial / step.scene));
            for (std::string line; std::getline(file, line);)
                lines.insert(trimmed(line));
            const std::size_t start = at + fence.size();
            std::istringstream block(
                step.text.substr(start, step.text.find("```\n", start) - start));
            for (std::string line; std::getline(block, line);)
                EXPECT_TRUE(lines.count(trimmed(line))) << step.scene << ": " << line;
        }
    }
    EXPECT_GE(blocks, 8);
}

// Every scene rendered once, small, with its warnings on (no --quiet): 41 x 31 pixels, so that
// the centre pixel's centre is the image's centre.
constexpr int kWidth = 41, kHeight = 31;

struct Render {
    RunResult run;
    Image image;
};

class TutorialRender : public testing::Test {
protected:
    static void SetUpTestSuite() {
        renders_ = std::make_unique<std::map<std::string, Render>>();
        const TempFolder folder;
        for (const std::string& name : scenesOfTheFolder()) {
            const std::string output = fs::path(name).replace_extension(".pfm").string();
            Render render;
            render.run = runLancer(
                {(kTutorial / name).string(), "-o", output, "--width", std::to_string(kWidth),
                 "--height", std::to_string(kHeight), "--spp", "1"},
                folder.path());
            if (render.run.exitStatus == 0) render.image = loadImage(folder / output);
            renders_->emplace(name, std::move(render));
        }
    }
    static void TearDownTestSuite() { renders_.reset(); }

    static const Render& renderOf(const std::string& name) { return renders_->at(name); }

    static std::unique_ptr<std::map<std::string, Render>> renders_;
};
std::unique_ptr<std::map<std::string, Render>> TutorialRender::renders_;

// Without --quiet, lancer's stderr holds its summary line, and for radiosity the solution's line,
// and nothing else unless something is wrong (a warning, an error).
TEST_F(TutorialRender, EverySceneRendersWithoutAWarning) {
    ASSERT_GE(scenesOfTheFolder().size(), 8u);
    for (const std::string& name : scenesOfTheFolder()) {
        const Render& render = renderOf(name);
        EXPECT_EQ(render.run.exitStatus, 0) << name << ": " << render.run;
        const std::string summary =
            "lancer: " + fs::path(name).replace_extension(".pfm").string() + ": ";
        for (const std::string& line : render.run.errorLines())
            EXPECT_TRUE(line.rfind(summary, 0) == 0 || line.rfind("lancer: radiosity: ", 0) == 0)
                << name << ": " << line;
        EXPECT_EQ(render.image.width, kWidth) << name;
    }
}

// Step 1: the sphere covers the centre, lit head-on by the directional light from behind the
// camera, so there Whitted's equation gives kd * E * cos(0) = kd * E exactly; a corner shows
// the background.
TEST_F(TutorialRender, TheFirstSphereIsLitAsLambertSaysAndTheCornerIsTheBackground) {
    const Image& image = renderOf("01-first-sphere.json").image;
    ASSERT_EQ(image.width, kWidth);
    const Image::Rgb kd{0.8f, 0.1f, 0.1f}, background{0.2f, 0.3f, 0.5f};
    const float irradiance = 1;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(image.at(kWidth / 2, kHeight / 2)[c], kd[c] * irradiance, 1e-4) << c;
        EXPECT_FLOAT_EQ(image.at(0, 0)[c], background[c]) << c;
    }
}

// The mean colour of a block of pixels.
Image::Rgb meanOf(const Image& image, int x0, int y0, int x1, int y1) {
    Image::Rgb sum{0, 0, 0};
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c)
                sum[c] += image.at(x, y)[c];
    const float count = static_cast<float>((x1 - x0) * (y1 - y0));
    for (float& value : sum)
        value /= count;
    return sum;
}

// Step 8: the ceiling, which the lamp under it does not light (the path tracer's direct light,
// --max-depth 1, leaves it black), is lit by radiosity with the light the walls reflect, and its
// end by the red wall is redder than its end by the green wall (colour bleeding).
TEST_F(TutorialRender, TheCornellBoxCeilingIsLitByTheWallsAndTakesTheirColours) {
    const std::string name = "08-cornell-box-radiosity.json";
    const Image& radiosity = renderOf(name).image;
    ASSERT_EQ(radiosity.width, kWidth);
    // The ceiling's left and right ends, between the lamp and the walls (rows 1 to 3).
    const Image::Rgb left = meanOf(radiosity, 8, 1, 12, 4), right = meanOf(radiosity, 28, 1, 32, 4);
    for (int c = 0; c < 3; ++c) {
        // The lamp is orange (emission 17, 12, 4): blue is the faintest, about 0.01.
        EXPECT_GT(left[c], 0.002f) << c;
        EXPECT_GT(right[c], 0.002f) << c;
    }
    EXPECT_GT(left[0] / left[1], 1.5f * (right[0] / right[1]));

    const Image direct =
        renderSceneFile(kTutorial / name,
                        {"--width", std::to_string(kWidth), "--height", std::to_string(kHeight),
                         "--spp", "1", "--integrator", "path", "--max-depth", "1"})
            .image;
    for (const Image::Rgb& end : {meanOf(direct, 8, 1, 12, 4), meanOf(direct, 28, 1, 32, 4)})
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(end[c], 0.0f) << c;
}

}  // namespace
}  // namespace lancer::test
