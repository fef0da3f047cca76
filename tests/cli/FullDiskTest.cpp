// A write that fails part-way, as on a full disk (here a file-size limit, which fails writes past
// it the same way): exit status 1, one line, no temporary file, and an earlier output left as it
// was. FreeImage's own file output reported no error for most formats, and the truncated file was
// renamed into place.

#include <gtest/gtest.h>

#include "LancerRun.h"

#ifndef _WIN32

namespace lancer::test {
namespace {

// Far smaller than any of the images below (the smallest, the JPEG, takes about 2 KB).
constexpr std::size_t kRoomOnDisk = 512;

class CliFullDisk : public testing::TestWithParam<std::string> {
protected:
    // Renders a small image to out.EXT with room for kRoomOnDisk bytes per file; checks the exit
    // status and the message, and returns the folder's listing after.
    std::vector<std::string> runWithoutRoom(const TempFolder& folder) {
        nlohmann::json scene = loadWhittedScene();
        scene["render"] = {{"width", 64}, {"height", 48}, {"spp", 1}};
        folder.write("scene.json", scene.dump());
        const std::string output = "out" + GetParam();
        const RunResult run =
            LancerProcess({"scene.json", "-o", output, "--quiet"}, folder.path(), kRoomOnDisk)
                .wait();
        EXPECT_EQ(run.exitStatus, 1) << run;
        EXPECT_EQ(run.errorLines(),
                  std::vector<std::string>{"lancer: error: " + output +
                                           ": cannot write the image (File too large)"})
            << run;
        return folder.entries();
    }
};

TEST_P(CliFullDisk, FailsWithOneLineAndLeavesNoFile) {
    const TempFolder folder;
    EXPECT_EQ(runWithoutRoom(folder), std::vector<std::string>{"scene.json"});
}

TEST_P(CliFullDisk, LeavesAnEarlierOutputAsItWas) {
    const TempFolder folder;
    const std::string earlier = "an image from an earlier run\n";
    folder.write("out" + GetParam(), earlier);
    EXPECT_EQ(runWithoutRoom(folder), (std::vector<std::string>{"out" + GetParam(), "scene.json"}));
    EXPECT_EQ(readFile(folder / ("out" + GetParam())), earlier);
}

INSTANTIATE_TEST_SUITE_P(Formats, CliFullDisk,
                         testing::Values(".png", ".jpg", ".bmp", ".tga", ".tif", ".exr", ".hdr",
                                         ".pfm"),
                         [](const testing::TestParamInfo<std::string>& test) {
                             return test.param.substr(1);
                         });

}  // namespace
}  // namespace lancer::test

#endif
