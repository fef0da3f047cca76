// The model cache end to end: a large OBJ model is kept on the first render and taken from the
// cache on the next, for the same image byte for byte; --no-model-cache keeps nothing; a damaged
// entry is a warning and the model is read from its file.

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>

#include "LancerRun.h"

namespace lancer::test {
namespace {

using json = nlohmann::json;

class CliModelCache : public ::testing::Test {
protected:
    CliModelCache() {
        // A small model made large (past the cache's 8 MiB) by a comment, as exported models
        // are by their many vertices.
        std::string obj = "# " + std::string(9 << 20, 'x') + "\n";
        obj += "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0.5\nv 0 0 1\n";
        obj += "f 1 2 5\nf 2 3 5\nf 3 4 5\nf 4 1 5\nf 1 1 2\n";  // a degenerate face: a warning
        folder_.write("model.obj", obj);
        const json scene = {
            {"render", {{"width", 32}, {"height", 24}, {"spp", 1}}},
            {"camera", {{"position", {0.5, -2, 3}}, {"look_at", {0, 0, 0.3}}}},
            {"objects", {{{"type", "mesh"}, {"file", "model.obj"}}}},
            {"lights", {{{"type", "point"}, {"position", {1, -2, 4}}, {"intensity", 20}}}}};
        folder_.write("scene.json", scene.dump());
    }

    RunResult render(const std::string& output, const std::vector<std::string>& options) const {
        std::vector<std::string> arguments{"scene.json", "-o", output};
        arguments.insert(arguments.end(), options.begin(), options.end());
        return runLancer(arguments, folder_.path());
    }

    TempFolder folder_;
    const std::vector<std::string> cached_{"--model-cache", "cache"};
};

TEST_F(CliModelCache, TheSecondRenderTakesTheModelFromTheCacheForTheSameImage) {
    const RunResult first = render("first.pfm", cached_);
    ASSERT_EQ(first.exitStatus, 0) << first;
    ASSERT_EQ(folder_.entries("cache").size(), 1u);
    // Dated back, so that an entry written again would show.
    const fs::path entry = folder_ / "cache" / folder_.entries("cache").front();
    const fs::file_time_type longAgo = fs::last_write_time(entry) - std::chrono::hours(24);
    fs::last_write_time(entry, longAgo);
    std::vector<std::string> withStats = cached_;
    withStats.push_back("--stats");
    const RunResult second = render("second.pfm", withStats);
    ASSERT_EQ(second.exitStatus, 0) << second;
    EXPECT_EQ(fs::last_write_time(entry), longAgo);  // read, not written
    EXPECT_NE(
        second.standardError.find("s of it building BVHs; 1 model taken from the model cache)"),
        std::string::npos)
        << second;
    const RunResult uncached = render("uncached.pfm", {"--no-model-cache"});
    ASSERT_EQ(uncached.exitStatus, 0) << uncached;

    const std::string image = readFile(folder_ / "first.pfm");
    EXPECT_EQ(readFile(folder_ / "second.pfm"), image);
    EXPECT_EQ(readFile(folder_ / "uncached.pfm"), image);
    EXPECT_GT(meanValue(loadImage(folder_ / "first.pfm")), 0.01);
    // The model's warning, given by each run alike.
    EXPECT_NE(first.standardError.find("zero-area triangle"), std::string::npos) << first;
    EXPECT_EQ(second.errorLines().front(), first.errorLines().front());
}

TEST_F(CliModelCache, AnAnimationReadsTheModelOnceForAllItsFrames) {
    json scene = json::parse(readFile(folder_ / "scene.json"));
    scene["animation"] = {
        {"frames", 3},
        {"camera",
         {{{"frame", 1}, {"position", {0.5, -2, 3}}}, {{"frame", 3}, {"position", {1, -2, 3}}}}}};
    folder_.write("animated.json", scene.dump());
    std::vector<std::string> arguments{"animated.json", "-o", "frame.pfm", "--stats"};
    arguments.insert(arguments.end(), cached_.begin(), cached_.end());
    const RunResult run = runLancer(arguments, folder_.path());
    ASSERT_EQ(run.exitStatus, 0) << run;
    std::size_t fromCache = 0;
    for (std::size_t at = 0; (at = run.standardError.find("1 model taken from the model cache",
                                                          at)) != std::string::npos;
         ++at)
        ++fromCache;
    EXPECT_EQ(fromCache, 2u) << run;  // frames 2 and 3
    for (const char* frame : {"frame-0001.pfm", "frame-0002.pfm", "frame-0003.pfm"})
        EXPECT_TRUE(fs::exists(folder_ / frame)) << frame;
}

TEST_F(CliModelCache, NoModelCacheKeepsNothing) {
    const RunResult run = render("out.pfm", {"--no-model-cache"});
    ASSERT_EQ(run.exitStatus, 0) << run;
    EXPECT_FALSE(fs::exists(folder_ / "cache"));
    const RunResult both = render("out.pfm", {"--no-model-cache", "--model-cache", "cache"});
    EXPECT_EQ(both.exitStatus, 2) << both;
    ASSERT_EQ(both.errorLines().size(), 1u) << both;
    EXPECT_NE(both.standardError.find("--no-model-cache"), std::string::npos) << both;
}

TEST_F(CliModelCache, ADamagedEntryIsAWarningAndTheModelIsReadAgain) {
    ASSERT_EQ(render("first.pfm", cached_).exitStatus, 0);
    ASSERT_EQ(folder_.entries("cache").size(), 1u);
    const fs::path entry = folder_ / "cache" / folder_.entries("cache").front();
    fs::resize_file(entry, fs::file_size(entry) / 2);

    const RunResult damaged = render("second.pfm", cached_);
    ASSERT_EQ(damaged.exitStatus, 0) << damaged;
    EXPECT_NE(damaged.standardError.find(entry.filename().string() +
                                         ": warning: the model cache entry is truncated"),
              std::string::npos)
        << damaged;
    EXPECT_EQ(readFile(folder_ / "second.pfm"), readFile(folder_ / "first.pfm"));
    // The entry was made anew, whole.
    const RunResult third = render("third.pfm", cached_);
    EXPECT_EQ(third.standardError.find("model cache entry"), std::string::npos) << third;
    EXPECT_EQ(readFile(folder_ / "third.pfm"), readFile(folder_ / "first.pfm"));
}

}  // namespace
}  // namespace lancer::test
