#include "io/IoLibraries.h"

#include <FreeImage.h>

#include <nlohmann/json.hpp>

#if LANCER_WITH_OPENEXR
#include <OpenEXRConfig.h>
#endif

namespace lancer {

std::string IoLibraries::versions() {
    // FreeImage's version is the library's at run time; the header-only ones', as
    // compiled. tinyobjloader's header has no version: CMake passes its package's. OpenEXR's
    // (FreeImage's, whose thread pool lancer sizes) when the build found its headers.
    std::string versions = std::string("FreeImage ") + FreeImage_GetVersion() + ", nlohmann-json " +
                           std::to_string(NLOHMANN_JSON_VERSION_MAJOR) + "." +
                           std::to_string(NLOHMANN_JSON_VERSION_MINOR) + "." +
                           std::to_string(NLOHMANN_JSON_VERSION_PATCH) + ", tinyobjloader " +
                           LANCER_TINYOBJLOADER_VERSION;
#if LANCER_WITH_OPENEXR
    versions += ", OpenEXR " OPENEXR_VERSION_STRING;
#endif
    return versions;
}

}  // namespace lancer
