// Output formats: 8-bit formats hold the clamped, sRGB-encoded image; float formats the linear
// radiance. The test scenes have no objects, so every pixel is the background's radiance.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "LancerRun.h"

namespace lancer::test {
namespace {

using Rgb = std::array<double, 3>;

// A 5x4 picture of nothing but the background `radiance`, one sample per pixel (so that each
// pixel holds the radiance itself, not an average of copies of it).
nlohmann::json backgroundOnlyScene(const Rgb& radiance) {
    nlohmann::json scene = nlohmann::json::parse(R"({
      "render": { "width": 5, "height": 4, "spp": 1 },
      "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }
    })");
    scene["background"] = radiance;
    return scene;
}

// The sRGB encoding of the contract (IEC 61966-2-1), in double precision.
double linearToSrgb(double v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

double srgbByte(double radiance) {
    return std::round(255 * linearToSrgb(std::clamp(radiance, 0.0, 1.0)));
}

void expectEveryPixel(const Image& image, const std::array<float, 3>& expected, double tolerance) {
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (std::size_t c = 0; c < 3; ++c)
                EXPECT_NEAR(image.at(x, y)[c], expected[c], tolerance)
                    << "at (" << x << ", " << y << "), channel " << c;
}

struct RadianceCase {
    std::string name;
    Rgb radiance;
};

std::ostream& operator<<(std::ostream& out, const RadianceCase& c) {
    return out << c.name;
}

class CliRadianceEncoding : public testing::TestWithParam<RadianceCase> {};

TEST_P(CliRadianceEncoding, PngHoldsRoundedSrgbOfTheClampedRadiance) {
    const Image image = renderScene(backgroundOnlyScene(GetParam().radiance), {}, "out.png").image;
    ASSERT_EQ(image.encoding, Image::Encoding::EightBit);
    ASSERT_EQ(image.width, 5);
    ASSERT_EQ(image.height, 4);

    std::array<float, 3> expected{};
    for (std::size_t c = 0; c < 3; ++c) {
        const double exact = 255 * linearToSrgb(std::clamp(GetParam().radiance[c], 0.0, 1.0));
        // The cases avoid values whose rounding float arithmetic could tip either way.
        ASSERT_GT(std::abs(exact - std::floor(exact) - 0.5), 0.01) << "a poor test value";
        expected[c] = static_cast<float>(srgbByte(GetParam().radiance[c]));
    }
    expectEveryPixel(image, expected, 0);  // exact: one rounding, the one the contract asks
}

TEST_P(CliRadianceEncoding, PfmHoldsTheLinearRadianceExactly) {
    const Image image = renderScene(backgroundOnlyScene(GetParam().radiance), {}, "out.pfm").image;
    ASSERT_EQ(image.encoding, Image::Encoding::LinearFloat);
    std::array<float, 3> expected{};
    for (std::size_t c = 0; c < 3; ++c)
        expected[c] = static_cast<float>(GetParam().radiance[c]);
    expectEveryPixel(image, expected, 0);  // no gamma, no clamping, no rounding beyond float's
}

INSTANTIATE_TEST_SUITE_P(
    Radiances, CliRadianceEncoding,
    testing::Values(RadianceCase{"Black", {0, 0, 0}},
                    // Below and above the end of sRGB's linear segment (0.0031308).
                    RadianceCase{"Dark", {0.001, 0.003, 0.02}},
                    RadianceCase{"Middle", {0.05, 0.2, 0.5}},
                    RadianceCase{"Bright", {0.8, 0.95, 1}},
                    RadianceCase{"AboveOneIsClamped", {1.5, 10, 1000}}),
    CaseName());

struct FormatCase {
    std::string name;
    std::string output;
    Image::Encoding encoding;
    double tolerance;  // on each channel: radiance for float formats, 0..255 values for 8-bit
};

std::ostream& operator<<(std::ostream& out, const FormatCase& c) {
    return out << c.name;
}

class CliOutputFormat : public testing::TestWithParam<FormatCase> {};

TEST_P(CliOutputFormat, IsWrittenAndLoadsBackWithTheImage) {
    // A colour with a channel above 1: kept by float formats, clamped by 8-bit ones.
    const Rgb radiance{0.05, 0.2, 2.5};
    const Image image = renderScene(backgroundOnlyScene(radiance), {}, GetParam().output).image;
    ASSERT_EQ(image.encoding, GetParam().encoding);
    ASSERT_EQ(image.width, 5);
    ASSERT_EQ(image.height, 4);

    std::array<float, 3> expected{};
    for (std::size_t c = 0; c < 3; ++c)
        expected[c] = static_cast<float>(GetParam().encoding == Image::Encoding::LinearFloat
                                             ? radiance[c]
                                             : srgbByte(radiance[c]));
    expectEveryPixel(image, expected, GetParam().tolerance);
}

INSTANTIATE_TEST_SUITE_P(
    Formats, CliOutputFormat,
    testing::Values(FormatCase{"Pfm", "out.pfm", Image::Encoding::LinearFloat, 0},
                    // Written with 32-bit floats: exact.
                    FormatCase{"Exr", "out.exr", Image::Encoding::LinearFloat, 0},
                    // RGBE: an 8-bit mantissa per channel under the largest channel's exponent,
                    // truncated, so an error up to one step, less than 2.5 / 128 ~ 0.02, on
                    // every channel.
                    FormatCase{"Hdr", "out.hdr", Image::Encoding::LinearFloat, 0.02},
                    FormatCase{"Png", "out.png", Image::Encoding::EightBit, 0},
                    // Lossy, but a flat colour survives within a few levels (colour conversion
                    // to YCbCr and back rounds each way).
                    FormatCase{"Jpg", "out.jpg", Image::Encoding::EightBit, 3},
                    FormatCase{"Bmp", "out.bmp", Image::Encoding::EightBit, 0},
                    FormatCase{"Tga", "out.tga", Image::Encoding::EightBit, 0},
                    FormatCase{"Tif", "out.tif", Image::Encoding::EightBit, 0}),
    CaseName());

// EXR is written with ZIP compression (OpenEXR's code 3 in the header's "compression"
// attribute), which on noisy renders packs as well as PIZ in a third of the time.
TEST(CliExrOutput, IsZipCompressed) {
    const std::string bytes =
        renderScene(backgroundOnlyScene({0.1, 0.2, 0.3}), {}, "out.exr").bytes;
    // The attribute: its name, its type name, a 4-byte little-endian size of 1, the value.
    const std::string attribute("compression\0compression\0\1\0\0\0", 28);
    const std::size_t at = bytes.find(attribute);
    ASSERT_NE(at, std::string::npos);
    ASSERT_LT(at + attribute.size(), bytes.size());
    EXPECT_EQ(static_cast<int>(bytes[at + attribute.size()]), 3);
}

// The image the right way up in every format: a floor below the horizon, the sky above. PFM is
// the trap: it stores the bottom row first, which FreeImage's PFM writer gets wrong (loadImage
// reads PFM by the netpbm definition, not through FreeImage).
TEST(CliOutputOrientation, EveryFormatHasTheSkyAtTheTop) {
    const nlohmann::json scene = nlohmann::json::parse(R"({
      "render": { "width": 4, "height": 6, "spp": 1 },
      "camera": { "position": [0, 1, 0], "look_at": [0, 1, -1], "vfov": 90 },
      "background": [0, 0, 1],
      "ambient": [1, 1, 1],
      "materials": { "floor": { "diffuse": [1, 0, 0] } },
      "objects": [ { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
                     "material": "floor" } ]
    })");
    for (const char* output : {"out.pfm", "out.exr", "out.png"}) {
        const Image image = renderScene(scene, {}, output).image;
        EXPECT_EQ(image.at(0, 0)[0], 0) << output << ": top row is sky";
        EXPECT_GT(image.at(0, 0)[2], 0) << output << ": top row is sky";
        EXPECT_GT(image.at(0, 5)[0], 0) << output << ": bottom row is floor";
        EXPECT_EQ(image.at(0, 5)[2], 0) << output << ": bottom row is floor";
    }
}

}  // namespace
}  // namespace lancer::test
