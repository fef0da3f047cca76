#pragma once

#include <string>

namespace lancer {

// The third-party libraries io adapts (FreeImage, nlohmann-json, tinyobjloader, and OpenEXR
// where the build found it), for lancer --version: io is their only home.
class IoLibraries {
public:
    // "FreeImage 3.18.0, nlohmann-json 3.11.2, tinyobjloader 2rc10, OpenEXR 3.1.5".
    static std::string versions();
};

}  // namespace lancer
