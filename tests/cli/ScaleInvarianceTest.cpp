// A scene scaled by any factor renders the same picture: secondary rays (shadow, reflected,
// refracted) are offset by a bound on the hit point's rounding error, which scales with the scene,
// rather than by a fixed epsilon, which is too small for a large scene (shadow acne, speckles)
// and too large for a small one (light leaking, missed contacts).

#include <gtest/gtest.h>

#include "LancerRun.h"

namespace lancer::test {
namespace {

using nlohmann::json;

void scaleEach(json& numbers, double factor) {
    if (numbers.is_number()) {
        numbers = numbers.get<double>() * factor;
        return;
    }
    for (json& element : numbers)
        scaleEach(element, factor);
}

// `scene` with every length multiplied by `factor`: positions, radii, checker squares, the camera;
// point lights' intensities are multiplied by factor^2 so that the irradiance I / d^2 they give is
// unchanged. Directions, colours and angles stay as they are.
json scaledScene(json scene, double factor) {
    for (const char* key : {"position", "look_at", "focus_distance", "aperture"})
        if (scene["camera"].contains(key)) scaleEach(scene["camera"][key], factor);
    for (json& object : scene["objects"])
        for (const char* key : {"center", "radius", "point", "vertices"})
            if (object.contains(key)) scaleEach(object[key], factor);
    for (auto& [name, material] : scene["materials"].items())
        for (const char* key : {"diffuse", "ambient"})
            if (material.contains(key) && material[key].contains("checker")) {
                json& checker = material[key]["checker"];
                checker["scale"] = checker.value("scale", 1.0) * factor;
            }
    for (json& light : scene["lights"])
        if (light["type"] == "point") {
            scaleEach(light["position"], factor);
            if (light.value("falloff", "inverse_square") != "none")
                scaleEach(light["intensity"], factor * factor);
        }
    return scene;
}

struct ScaleCase {
    std::string name;
    double factor;
};

std::ostream& operator<<(std::ostream& out, const ScaleCase& c) {
    return out << c.name;
}

class CliScaleInvariance : public testing::TestWithParam<ScaleCase> {};

TEST_P(CliScaleInvariance, WhittedSceneRendersTheSamePictureAtAnyScale) {
    // The classic scene: checkered floor, mirror, glass and shiny spheres, a triangle, two point
    // lights; one sample per pixel, so that each pixel is one camera ray and its secondary rays.
    const json scene = loadWhittedScene();
    const std::vector<std::string> size{"--width", "160", "--height", "120", "--spp", "1"};
    const Image reference = renderScene(scene, size).image;
    const Image scaled = renderScene(scaledScene(scene, GetParam().factor), size).image;

    // The scaled scene's numbers are not exactly the scaled numbers (1e-3 is not a binary
    // fraction), so hit points move by float rounding: values agree to about 1e-5 relative, and a
    // camera ray that passes within rounding distance of a silhouette or a checker border may
    // land on the other side. 1e-3 relative (plus 1e-4 absolute for dark values) leaves room for
    // the first; the second happens to a handful of pixels at most (3 at 1e-3 and 1 at 1e4 when
    // this was written), 0.05% (10 of the 19200) is generous. Acne or speckles on the floor or
    // the glass would ruin hundreds of pixels (a fixed offset of 1e-4 ruins a third of them at
    // 1e-3 and 3% at 1e4), and would darken the image as a whole: the mean difference must stay
    // below 1e-4.
    EXPECT_GE(fractionOfPixelsWithin(scaled, reference, 1e-4, 1e-3), 0.9995);
    EXPECT_LT(meanAbsoluteDifference(scaled, reference), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Factors, CliScaleInvariance,
                         testing::Values(ScaleCase{"Thousandth", 1e-3},
                                         ScaleCase{"TenThousand", 1e4}),
                         CaseName());

}  // namespace
}  // namespace lancer::test
