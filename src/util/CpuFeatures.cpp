#include "util/CpuFeatures.h"

#include <cstdlib>
#include <string_view>

namespace lancer {

bool CpuFeatures::detectAvx2() {
    const char* asked = std::getenv("LANCER_SIMD");
    if (asked && std::string_view(asked) == "baseline") return false;
#if LANCER_HAS_AVX2_TARGET
    // libgcc's answer includes the system's support of the 256-bit registers (XGETBV).
    __builtin_cpu_init();  // this may run before libgcc's own initializer
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

void CpuFeatures::useBaselineOnly(bool baseline) {
    avx2_ = !baseline && detectAvx2();
}

}  // namespace lancer
