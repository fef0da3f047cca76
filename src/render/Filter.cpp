#include "render/Filter.h"

#include <stdexcept>

#include "render/BoxFilter.h"
#include "render/GaussianFilter.h"
#include "render/MitchellFilter.h"
#include "render/TentFilter.h"
#include "scene/FilterSettings.h"
#include "util/DidYouMean.h"

namespace lancer {

namespace {

template <typename FilterType>
std::unique_ptr<Filter> make(float radius) {
    return std::make_unique<FilterType>(radius);
}

}  // namespace

const Registry<Filter::Type>& Filter::types() {
    // Default radii: the box covers the pixel exactly (the plain average of the contract); the
    // tent reaches the neighbouring pixel centres; the Gaussian and Mitchell defaults are
    // pbrt-v4's (Mitchell and Netravali's kernel spans 2 pixels on each side).
    static const Registry<Type> filters{
        {"box", 0.5f, &make<BoxFilter>},
        {"tent", 1.0f, &make<TentFilter>},
        {"gaussian", 1.5f, &make<GaussianFilter>},
        {"mitchell", 2.0f, &make<MitchellFilter>},
    };
    return filters;
}

std::unique_ptr<Filter> Filter::create(const FilterSettings& settings) {
    const Type* type = types().find(settings.type);
    if (!type) throw std::invalid_argument(unknownName("filter", settings.type, types().names()));
    const float radius = settings.radius.value_or(type->defaultRadius);
    if (!(radius > 0)) throw std::invalid_argument("the filter radius must be greater than 0");
    return type->create(radius);
}

}  // namespace lancer
