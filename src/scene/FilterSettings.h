#pragma once

#include <optional>
#include <string>

namespace lancer {

// The "filter" of the scene's "render" block: which reconstruction filter, and its radius in
// pixels (the type's default when not given; see Filter::create).
struct FilterSettings {
    std::string type = "box";
    std::optional<float> radius;
};

}  // namespace lancer
