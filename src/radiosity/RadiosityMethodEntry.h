#pragma once

#include <memory>

#include "radiosity/RadiosityMethod.h"

namespace lancer {

class Scene;

// A radiosity method the scene's "radiosity" "method" key can name.
struct RadiosityMethodEntry {
    const char* name;
    std::unique_ptr<RadiosityMethod> (*create)(const Scene& scene);
};

}  // namespace lancer
