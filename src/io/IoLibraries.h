#pragma once

#include <string>

namespace lancer {

// The third-party libraries io adapts (FreeImage, nlohmann-json, tinyobjloader), for
// lancer --version: io is their only home.
class IoLibraries {
public:
    // "FreeImage 3.18.0, nlohmann-json 3.11.2, tinyobjloader 2rc10".
    static std::string versions();
};

}  // namespace lancer
