// Exposure and tone mapping (docs/SCENE-FORMAT.md, "Exposure, tone mapping and extra outputs"):
// scenes of nothing but a background of known radiance, so that every pixel is that radiance, and
// the stored values against the contract's formulas in double precision.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "LancerRun.h"

namespace lancer::test {
namespace {

// A 4x3 picture of the background `radiance`, one sample per pixel, with these render keys.
nlohmann::json backgroundScene(double radiance, const nlohmann::json& renderKeys) {
    nlohmann::json scene = nlohmann::json::parse(R"({
      "render": { "width": 4, "height": 3, "spp": 1 },
      "camera": { "position": [0, 0, 5], "look_at": [0, 0, 0] }
    })");
    scene["render"].update(renderKeys);
    scene["background"] = radiance;
    return scene;
}

double linearToSrgb(double v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

// The contract's operators.
double clampCurve(double c) {
    return std::min(c, 1.0);
}
double reinhardCurve(double c) {
    return c / (1 + c);
}
double acesCurve(double c) {
    return std::clamp(c * (2.51 * c + 0.03) / (c * (2.43 * c + 0.59) + 0.14), 0.0, 1.0);
}

struct ToneCase {
    std::string name;
    std::string tonemap;  // empty: the key is left out (the default)
    double exposure;      // stops; NaN: the key is left out
    double radiance;
    std::function<double(double)> curve;
};

std::ostream& operator<<(std::ostream& out, const ToneCase& c) {
    return out << c.name;
}

class CliToneMapping : public testing::TestWithParam<ToneCase> {};

TEST_P(CliToneMapping, PngHoldsTheSrgbOfTheOperatorOfTheExposedRadiance) {
    const ToneCase& c = GetParam();
    nlohmann::json keys = nlohmann::json::object();
    if (!c.tonemap.empty()) keys["tonemap"] = c.tonemap;
    if (!std::isnan(c.exposure)) keys["exposure"] = c.exposure;
    const double exposure = std::isnan(c.exposure) ? 0 : c.exposure;
    const double exact = 255 * linearToSrgb(c.curve(c.radiance * std::exp2(exposure)));
    // Away from a rounding tie, so that float arithmetic cannot tip the byte either way.
    ASSERT_GT(std::abs(exact - std::floor(exact) - 0.5), 0.02) << "a poor test value: " << exact;

    const Image image = renderScene(backgroundScene(c.radiance, keys), {}, "out.png").image;
    ASSERT_EQ(image.encoding, Image::Encoding::EightBit);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (std::size_t k = 0; k < 3; ++k)
                ASSERT_EQ(image.at(x, y)[k], std::round(exact)) << "at (" << x << ", " << y << ")";
}

// Radiances below, at and above 1, where the operators differ most; exposures that brighten and
// darken, whole and fractional.
INSTANTIATE_TEST_SUITE_P(
    Operators, CliToneMapping,
    testing::Values(ToneCase{"DefaultIsClamp", "", NAN, 0.3, clampCurve},
                    ToneCase{"ClampAboveOne", "clamp", NAN, 2.5, clampCurve},
                    ToneCase{"ClampWithExposure", "clamp", 1, 0.3, clampCurve},
                    ToneCase{"ClampWithNegativeExposure", "clamp", -1.5, 2.1, clampCurve},
                    ToneCase{"ReinhardBelowOne", "reinhard", 0, 0.3, reinhardCurve},
                    ToneCase{"ReinhardAboveOne", "reinhard", 0, 4.7, reinhardCurve},
                    ToneCase{"ReinhardWithExposure", "reinhard", 2, 0.7, reinhardCurve},
                    ToneCase{"AcesBelowOne", "aces", 0, 0.18, acesCurve},
                    ToneCase{"AcesAtOne", "aces", 0, 1.0, acesCurve},
                    ToneCase{"AcesWithExposure", "aces", -0.5, 1.6, acesCurve},
                    ToneCase{"AcesSaturates", "aces", 0, 20, acesCurve}),
    CaseName());

// Linear outputs are exposed but never tone mapped: the radiance times 2^exposure, to float
// rounding (one multiplication by a power of two is exact; 2^1.5 is one rounding of exp2).
TEST(CliExposure, ScalesThePfmByTwoToTheExposure) {
    for (const double exposure : {3.0, -2.0, 1.5}) {
        for (const std::string tonemap : {"clamp", "aces"}) {
            const double radiance = 2.75;
            const Image image = renderScene(backgroundScene(radiance, {{"exposure", exposure},
                                                                       {"tonemap", tonemap}}))
                                    .image;
            ASSERT_EQ(image.encoding, Image::Encoding::LinearFloat);
            const float expected =
                static_cast<float>(radiance) * std::exp2(static_cast<float>(exposure));
            for (int y = 0; y < image.height; ++y)
                for (int x = 0; x < image.width; ++x)
                    for (std::size_t k = 0; k < 3; ++k)
                        ASSERT_EQ(image.at(x, y)[k], expected)
                            << "exposure " << exposure << ", " << tonemap;
        }
    }
}

}  // namespace
}  // namespace lancer::test
