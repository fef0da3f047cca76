#include "materials/CheckerTexture.h"

#include <cmath>

namespace lancer {

CheckerTexture::CheckerTexture(const Color& even, const Color& odd, float scale)
    : even_(even), odd_(odd), scale_(scale) {}

std::shared_ptr<const Texture> CheckerTexture::create(const Parameters& parameters) {
    const Color even = parameters.has("even") ? parameters.color("even") : Color(1);
    const Color odd = parameters.has("odd") ? parameters.color("odd") : Color(0);
    const float scale = parameters.has("scale") ? parameters.numberAbove("scale", 0, false) : 1;
    return std::make_shared<CheckerTexture>(even, odd, scale);
}

Color CheckerTexture::evaluate(const Hit& hit) const {
    // In double: uv can be large world coordinates, and floor() of a float sum would misplace
    // square boundaries far from the origin.
    const auto cell = [this](float x) {
        return static_cast<long long>(std::floor(double(x) / scale_));
    };
    const Vec2 uv = hit.uv();
    return (cell(uv.x) + cell(uv.y)) % 2 == 0 ? even_ : odd_;
}

}  // namespace lancer
