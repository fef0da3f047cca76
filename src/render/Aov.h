#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "math/Color.h"
#include "render/AovSample.h"
#include "util/Registry.h"

namespace lancer {

// An auxiliary output that --aov can name: which part of an AovSample its image stores, as
// RGB (a normal's x, y, z; a depth in all three channels).
struct Aov {
    const char* name;
    Color (*value)(const AovSample& sample);

    // The outputs, by name: one registration line each.
    static const Registry<Aov>& types();

    // The outputs a comma-separated list names ("albedo,normal"), in its order, each once.
    // Throws std::invalid_argument for an empty list, an empty or unknown name (with the valid
    // ones and a suggestion) or a repeated one; its message starts with the quoted list.
    static std::vector<const Aov*> parseList(const std::string& list);

    // Where this output goes beside the image `output`: out.png -> out.albedo.exr.
    std::filesystem::path pathBeside(const std::filesystem::path& output) const;
};

}  // namespace lancer
