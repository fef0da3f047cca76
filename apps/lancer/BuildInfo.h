#pragma once

#include <string>

namespace lancer {

// What lancer --version says about the build: the compiler, the SIMD instructions compiled for,
// the libraries' versions, and whether it can run on a cluster (MPI).
class BuildInfo {
public:
    static std::string describe();
    // The same without the window's library (SDL2, which is loaded only to be asked its version):
    // what of the build can change an image.
    static std::string describeRendering();
};

}  // namespace lancer
