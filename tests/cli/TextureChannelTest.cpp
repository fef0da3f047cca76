// Textures for the material keys beside `diffuse`: `specular`, `reflection` (colours) and
// `roughness` (a map of numbers). A texture of two values must render, texel for texel, as the
// material with either value as a constant: the map replaces the factor where it is given.

#include <gtest/gtest.h>

#include <string>

#include "LancerRun.h"
#include "PfmFile.h"

namespace lancer::test {
namespace {

constexpr float kLow = 0.25f, kHigh = 0.75f;

// A floor y = 0 seen straight down by an orthographic camera (its uv are the world's (x, z): the
// texture repeats every unit), lit by a tilted sun, under a grey sky the mirrors reflect.
nlohmann::json floorScene(const nlohmann::json& material) {
    return {
        {"render", {{"width", 160}, {"height", 120}, {"spp", 1}, {"max_depth", 2}}},
        {"camera", cameraAlongY(0.1, 0.2, 5)},
        {"background", 0.5},
        {"materials", {{"floor", material}}},
        {"objects",
         {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "floor"}}}},
        {"lights", {{{"type", "directional"}, {"direction", {0.2, -1, 0.1}}, {"irradiance", 1}}}}};
}

struct Channel {
    std::string name;
    nlohmann::json material;  // the floor's material but the key under test
    std::string key;
};

std::ostream& operator<<(std::ostream& out, const Channel& c) {
    return out << c.name;
}

class CliTextureChannel : public testing::TestWithParam<Channel> {};

TEST_P(CliTextureChannel, MapRendersAsTheConstantOfEachTexel) {
    const Channel& channel = GetParam();
    // 64 texels a unit: the left half kLow, the right half kHigh in every channel, so that away
    // from the two edges (where the bilinear lookup blends them) each texel is one of the values.
    const TempFolder maps;
    lancer::Image halves(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            halves.at(x, y) = Color(x < 32 ? kLow : kHigh);
    writePfm(halves, maps / "halves.pfm");

    const auto render = [&](const nlohmann::json& value) {
        nlohmann::json material = channel.material;
        material[channel.key] = value;
        return renderScene(floorScene(material)).image;
    };
    const Image low = render(kLow), high = render(kHigh);
    const Image mapped = render({{"texture", (maps / "halves.pfm").string()}});
    // The two constants must look different, or the comparison proves nothing.
    ASSERT_GT(std::abs(meanValue(high) - meanValue(low)), 0.01) << channel.name;

    int asLow = 0, asHigh = 0;
    for (int y = 0; y < mapped.height; ++y)
        for (int x = 0; x < mapped.width; ++x) {
            bool sameAsLow = true, sameAsHigh = true;
            for (int c = 0; c < 3; ++c) {
                sameAsLow = sameAsLow && std::abs(mapped.at(x, y)[c] - low.at(x, y)[c]) <= 1e-6f;
                sameAsHigh = sameAsHigh && std::abs(mapped.at(x, y)[c] - high.at(x, y)[c]) <= 1e-6f;
            }
            asLow += sameAsLow;
            asHigh += sameAsHigh;
        }
    const int pixels = mapped.width * mapped.height;
    // Each half covers half the floor; the blended strips along the edges (a texel or two wide
    // every 32 texels at about a texel a pixel) are the rest.
    EXPECT_GT(asLow, pixels * 0.42) << channel.name;
    EXPECT_GT(asHigh, pixels * 0.42) << channel.name;
    EXPECT_GT(asLow + asHigh, pixels * 0.9) << channel.name;
}

INSTANTIATE_TEST_SUITE_P(
    Keys, CliTextureChannel,
    testing::Values(Channel{"Specular", {{"diffuse", 0.2}, {"shininess", 20}}, "specular"},
                    Channel{"Reflection", {{"diffuse", 0.2}}, "reflection"},
                    Channel{"ReflectionOfAMetal", {{"metal", "gold"}}, "reflection"},
                    Channel{"Roughness", {{"diffuse", 0}, {"reflection", 1}}, "roughness"},
                    Channel{
                        "RoughnessOfGlass", {{"diffuse", 0}, {"transmission", 1}}, "roughness"}),
    CaseName());

}  // namespace
}  // namespace lancer::test
