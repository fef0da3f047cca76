#include "BuildInfo.h"

#include <tbb/version.h>
#include <CLI/Version.hpp>

#include "Viewer.h"
#include "cluster/Cluster.h"
#include "io/IoLibraries.h"
#include "util/CpuFeatures.h"

namespace lancer {

namespace {

std::string compiler() {
#if defined(__clang__)
    return "Clang " __clang_version__;
#elif defined(__GNUC__)
    return "GCC " __VERSION__;
#elif defined(_MSC_VER)
    return "MSVC " + std::to_string(_MSC_FULL_VER);
#else
    return "an unknown compiler";
#endif
}

// The widest instruction set the compiler was allowed: every target of the build gets the same
// flags, so this is also what the core's SSE lanes (Float4, WideBvh's box tests) were built for.
const char* simdLevel() {
#if defined(__AVX512F__)
    return "AVX-512";
#elif defined(__AVX2__)
    return "AVX2";
#elif defined(__AVX__)
    return "AVX";
#elif defined(__SSE4_2__)
    return "SSE4.2";
#elif defined(__SSE4_1__)
    return "SSE4.1";
#elif defined(__SSE2__) || defined(_M_X64)
    return "SSE2";
#elif defined(__ARM_NEON)
    return "NEON";
#else
    return "no SIMD";
#endif
}

}  // namespace

std::string BuildInfo::describe() {
    return describeRendering() + ", " + Viewer::libraryVersion();
}

std::string BuildInfo::describeRendering() {
    return std::string("lancer ") + LANCER_VERSION + "\nbuilt with " + compiler() + " for " +
           simdLevel() + (CpuFeatures::avx2() ? " (AVX2 kernels on this CPU)" : "") + ", " +
           Cluster::describe() + "\nlibraries: " + IoLibraries::versions() + ", oneTBB " +
           TBB_VERSION_STRING + ", CLI11 " + CLI11_VERSION;
}

}  // namespace lancer
