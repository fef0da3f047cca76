#include "render/Filter.h"

#include <stdexcept>

#include "render/BoxFilter.h"
#include "render/GaussianFilter.h"
#include "render/MitchellFilter.h"
#include "render/TentFilter.h"
#include "scene/FilterSettings.h"

namespace lancer {

std::unique_ptr<Filter> Filter::create(const FilterSettings& settings) {
    // Default radii: the box covers the pixel exactly (the plain average of the contract); the
    // tent reaches the neighbouring pixel centres; the Gaussian and Mitchell defaults are
    // pbrt-v4's (Mitchell and Netravali's kernel spans 2 pixels on each side).
    const auto radius = [&](float byDefault) {
        const float r = settings.radius.value_or(byDefault);
        if (!(r > 0)) throw std::invalid_argument("the filter radius must be greater than 0");
        return r;
    };
    if (settings.type == "box") return std::make_unique<BoxFilter>(radius(0.5f));
    if (settings.type == "tent") return std::make_unique<TentFilter>(radius(1.0f));
    if (settings.type == "gaussian") return std::make_unique<GaussianFilter>(radius(1.5f));
    if (settings.type == "mitchell") return std::make_unique<MitchellFilter>(radius(2.0f));
    throw std::invalid_argument("unknown filter \"" + settings.type + "\"");
}

const std::vector<std::string>& Filter::typeNames() {
    static const std::vector<std::string> names{"box", "tent", "gaussian", "mitchell"};
    return names;
}

}  // namespace lancer
