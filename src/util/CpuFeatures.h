#pragma once

// GCC and clang compile a function for instructions beyond the build's baseline (x86-64: SSE2)
// when it carries a target attribute; the CPU is then asked at run time whether to call it.
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define LANCER_HAS_AVX2_TARGET 1
#define LANCER_AVX2_TARGET [[gnu::target("avx2")]]
#else
#define LANCER_HAS_AVX2_TARGET 0
#define LANCER_AVX2_TARGET
#endif

namespace lancer {

// What the CPU running lancer offers beyond the build's baseline, for the kernels chosen at run
// time (the default build runs on any x86-64). The kernels give the same bits whichever runs:
// the same operations lane by lane, never a fused multiply-add.
class CpuFeatures {
public:
    // Whether the AVX2 kernels run: the CPU and the system support AVX2, and neither the
    // environment (LANCER_SIMD=baseline) nor useBaselineOnly asked for the baseline.
    static bool avx2() { return avx2_; }
    // For tests and benchmarks: the baseline kernels only (true), or the CPU's best again.
    static void useBaselineOnly(bool baseline);

private:
    static bool detectAvx2();
    static inline bool avx2_ = detectAvx2();
};

}  // namespace lancer
