#pragma once

#include <string>

namespace lancer {

// What lancer --version says about the build: the compiler, the SIMD instructions compiled for,
// the libraries' versions, and whether it can run on a cluster (MPI).
class BuildInfo {
public:
    static std::string describe();
};

}  // namespace lancer
