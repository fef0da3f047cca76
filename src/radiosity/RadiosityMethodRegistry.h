#pragma once

#include "radiosity/RadiosityMethodEntry.h"
#include "util/Registry.h"

namespace lancer {

// The radiosity methods, by name: one registration line each.
class RadiosityMethodRegistry {
public:
    static const Registry<RadiosityMethodEntry>& table();
};

}  // namespace lancer
