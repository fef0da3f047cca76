#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

// Forces a function inline where the compiler's size heuristics would not, for code at the heart
// of a hot loop.
#if defined(__GNUC__)
#define LANCER_ALWAYS_INLINE [[gnu::always_inline]] inline
#elif defined(_MSC_VER)
#define LANCER_ALWAYS_INLINE __forceinline
#else
#define LANCER_ALWAYS_INLINE inline
#endif

// The same for a lambda, written after its parameter list: for the leaf tests that a traversal
// calls, which it then compiles for its own instruction set, with no call, spill or AVX-to-SSE
// transition between them.
#if defined(__GNUC__)
#define LANCER_INLINE_LAMBDA __attribute__((always_inline))
#else
#define LANCER_INLINE_LAMBDA
#endif

// Keeps a function out of line, so that a small caller that may not need it is not burdened with
// its frame.
#if defined(__GNUC__)
#define LANCER_NEVER_INLINE [[gnu::noinline]]
#elif defined(_MSC_VER)
#define LANCER_NEVER_INLINE __declspec(noinline)
#else
#define LANCER_NEVER_INLINE
#endif

namespace lancer {

constexpr float kPi = std::numbers::pi_v<float>;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The largest float below 1: the top of sample ranges [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

// Half a unit in the last place: the bound on the relative rounding error of one float operation.
constexpr float kMachineEpsilon = std::numeric_limits<float>::epsilon() * 0.5f;

// Bound on the relative error accumulated by n successive float operations (Higham's gamma_n,
// as used by pbrt to bound the error of computed intersection points).
constexpr float gamma(int n) {
    return (static_cast<float>(n) * kMachineEpsilon) /
           (1.0f - static_cast<float>(n) * kMachineEpsilon);
}

// The next float above (below) v: std::nextafter towards +infinity (-infinity), by stepping the
// bit pattern (pbrt's NextFloatUp), inline where ray origins are offset.
inline float nextFloatUp(float v) {
    if (std::isinf(v) && v > 0) return v;
    if (v == 0) v = 0.0f;  // -0 steps up as +0 does
    const auto bits = std::bit_cast<std::uint32_t>(v);
    return std::bit_cast<float>(v >= 0 ? bits + 1 : bits - 1);
}
inline float nextFloatDown(float v) {
    if (std::isinf(v) && v < 0) return v;
    if (v == 0) v = -0.0f;  // +0 steps down as -0 does
    const auto bits = std::bit_cast<std::uint32_t>(v);
    return std::bit_cast<float>(v > 0 ? bits - 1 : bits + 1);
}

constexpr float radians(float degrees) {
    return degrees * (kPi / 180.0f);
}

template <typename T>
constexpr T clamp(T v, T lo, T hi) {
    return v < lo ? lo : (v > hi ? hi : v);
}

}  // namespace lancer
