#include "io/IoLibraries.h"

#include <FreeImage.h>

#include <nlohmann/json.hpp>

namespace lancer {

std::string IoLibraries::versions() {
    // FreeImage's version is the library's at run time; the header-only ones', as
    // compiled. tinyobjloader's header has no version: CMake passes its package's.
    return std::string("FreeImage ") + FreeImage_GetVersion() + ", nlohmann-json " +
           std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
           std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
           std::to_string(NLOHMANN_JSON_VERSION_PATCH) + ", tinyobjloader " +
           LANCER_TINYOBJLOADER_VERSION;
}

}  // namespace lancer
