#include "radiosity/RadiosityMethodRegistry.h"

#include "radiosity/HierarchicalRadiosity.h"
#include "radiosity/ProgressiveRadiosity.h"

namespace lancer {

namespace {

template <typename Method>
std::unique_ptr<RadiosityMethod> create(const Scene& scene) {
    return std::make_unique<Method>(scene);
}

}  // namespace

const Registry<RadiosityMethodEntry>& RadiosityMethodRegistry::table() {
    static const Registry<RadiosityMethodEntry> methods{
        {"progressive", create<ProgressiveRadiosity>},
        {"hierarchical", create<HierarchicalRadiosity>},
    };
    return methods;
}

}  // namespace lancer
