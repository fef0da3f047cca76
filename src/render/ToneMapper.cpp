#include "render/ToneMapper.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "math/Float.h"
#include "util/DidYouMean.h"
#include "util/ParallelFor.h"

namespace lancer {

namespace {

// "clamp": the radiance itself, clamped to [0, 1] as every curve is.
float identityCurve(float c) {
    return c;
}

// Reinhard, Stark, Shirley and Ferwerda (2002), the simple global operator.
float reinhardCurve(float c) {
    return c / (1 + c);
}

// Narkowicz's fit (2015) of the ACES filmic curve.
float acesCurve(float c) {
    return c * (2.51f * c + 0.03f) / (c * (2.43f * c + 0.59f) + 0.14f);
}

}  // namespace

const Registry<ToneMapper::Operator>& ToneMapper::operators() {
    static const Registry<Operator> operators{
        {"clamp", &identityCurve},
        {"reinhard", &reinhardCurve},
        {"aces", &acesCurve},
    };
    return operators;
}

ToneMapper::ToneMapper(float exposure, std::string_view operatorName)
    : scale_(std::exp2(exposure)), operator_(operators().find(operatorName)) {
    if (!operator_)
        throw std::invalid_argument(
            unknownName("tonemap", std::string(operatorName), operators().names()));
}

Color ToneMapper::display(const Color& radiance) const {
    // Negative or NaN radiance (never expected) shows as black rather than through a curve
    // that is not meant for it: the curves see c > 0 only. A curve that overflows to NaN
    // (infinity over infinity, for radiance near the float range) is at its limit, which is 1
    // or more for every operator.
    const auto map = [&](float c) {
        const float x = c * scale_;
        if (!(x > 0)) return 0.0f;
        const float y = operator_->curve(x);
        return std::isnan(y) ? 1.0f : clamp(y, 0.0f, 1.0f);
    };
    return {map(radiance.r), map(radiance.g), map(radiance.b)};
}

void ToneMapper::mapForOutput(Image& film, bool linear) const {
    // Rows on all the render's threads: the image waits for this after the render.
    parallelFor(static_cast<std::size_t>(film.height()), 16, [&](std::size_t row) {
        const int y = static_cast<int>(row);
        for (int x = 0; x < film.width(); ++x) {
            Color& c = film.at(x, y);
            c = linear ? exposed(c) : display(c);
        }
    });
}

}  // namespace lancer
