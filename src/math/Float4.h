#pragma once

#include <cmath>

#include "math/Float.h"

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define LANCER_FLOAT4_SSE 1
#endif

namespace lancer {

// Four floats computed on together: one SSE register where the target has SSE2 (every x86-64),
// four plain floats elsewhere. Each operation rounds lane by lane exactly as the scalar operation
// it stands for (no fused multiply-add, no approximate reciprocal), so that code written with it
// gives the bits of the same code written on floats. Comparisons give a bit mask, bit i for lane
// i, false on NaN as in C++ (except ne).
class Float4 {
public:
    static constexpr int kAllLanes = 0xf;

    Float4() = default;
    // The same value in all four lanes.
    explicit Float4(float v) {
#ifdef LANCER_FLOAT4_SSE
        v_ = _mm_set1_ps(v);
#else
        for (float& lane : v_)
            lane = v;
#endif
    }
    // From 16-byte aligned memory (which SSE code can read as an operand of the arithmetic).
    static Float4 load(const float* p) {
#ifdef LANCER_FLOAT4_SSE
        return Float4(_mm_load_ps(p));
#else
        return loadUnaligned(p);
#endif
    }
    // From any address.
    static Float4 loadUnaligned(const float* p) {
        Float4 r;
#ifdef LANCER_FLOAT4_SSE
        r.v_ = _mm_loadu_ps(p);
#else
        for (int i = 0; i < 4; ++i)
            r.v_[i] = p[i];
#endif
        return r;
    }
    void store(float* p) const {
#ifdef LANCER_FLOAT4_SSE
        _mm_storeu_ps(p, v_);
#else
        for (int i = 0; i < 4; ++i)
            p[i] = v_[i];
#endif
    }

#ifdef LANCER_FLOAT4_SSE
    friend Float4 operator+(Float4 a, Float4 b) {
        return Float4(_mm_add_ps(a.v_, b.v_));
    }
    friend Float4 operator-(Float4 a, Float4 b) {
        return Float4(_mm_sub_ps(a.v_, b.v_));
    }
    friend Float4 operator*(Float4 a, Float4 b) {
        return Float4(_mm_mul_ps(a.v_, b.v_));
    }
    friend Float4 operator/(Float4 a, Float4 b) {
        return Float4(_mm_div_ps(a.v_, b.v_));
    }
    friend Float4 abs(Float4 a) {
        return Float4(_mm_andnot_ps(_mm_set1_ps(-0.0f), a.v_));
    }
    // std::max(a, b) and std::min(a, b): a unless b is greater (smaller), so a when either is
    // NaN. maxps and minps return their second operand unless the first is greater (smaller).
    friend Float4 max(Float4 a, Float4 b) {
        return Float4(_mm_max_ps(b.v_, a.v_));
    }
    friend Float4 min(Float4 a, Float4 b) {
        return Float4(_mm_min_ps(b.v_, a.v_));
    }

    friend int lt(Float4 a, Float4 b) {
        return _mm_movemask_ps(_mm_cmplt_ps(a.v_, b.v_));
    }
    friend int le(Float4 a, Float4 b) {
        return _mm_movemask_ps(_mm_cmple_ps(a.v_, b.v_));
    }
    friend int gt(Float4 a, Float4 b) {
        return _mm_movemask_ps(_mm_cmpgt_ps(a.v_, b.v_));
    }
    friend int ge(Float4 a, Float4 b) {
        return _mm_movemask_ps(_mm_cmpge_ps(a.v_, b.v_));
    }
    friend int eq(Float4 a, Float4 b) {
        return _mm_movemask_ps(_mm_cmpeq_ps(a.v_, b.v_));
    }
    friend int ne(Float4 a, Float4 b) {
        return _mm_movemask_ps(_mm_cmpneq_ps(a.v_, b.v_));
    }

private:
    explicit Float4(__m128 v) : v_(v) {}

    __m128 v_;
#else
    friend Float4 operator+(Float4 a, Float4 b) {
        return map(a, b, [](float x, float y) { return x + y; });
    }
    friend Float4 operator-(Float4 a, Float4 b) {
        return map(a, b, [](float x, float y) { return x - y; });
    }
    friend Float4 operator*(Float4 a, Float4 b) {
        return map(a, b, [](float x, float y) { return x * y; });
    }
    friend Float4 operator/(Float4 a, Float4 b) {
        return map(a, b, [](float x, float y) { return x / y; });
    }
    friend Float4 abs(Float4 a) {
        return map(a, a, [](float x, float) { return std::abs(x); });
    }
    friend Float4 max(Float4 a, Float4 b) {
        return map(a, b, [](float x, float y) { return x < y ? y : x; });
    }
    friend Float4 min(Float4 a, Float4 b) {
        return map(a, b, [](float x, float y) { return y < x ? y : x; });
    }

    friend int lt(Float4 a, Float4 b) {
        return mask(a, b, [](float x, float y) { return x < y; });
    }
    friend int le(Float4 a, Float4 b) {
        return mask(a, b, [](float x, float y) { return x <= y; });
    }
    friend int gt(Float4 a, Float4 b) {
        return mask(a, b, [](float x, float y) { return x > y; });
    }
    friend int ge(Float4 a, Float4 b) {
        return mask(a, b, [](float x, float y) { return x >= y; });
    }
    friend int eq(Float4 a, Float4 b) {
        return mask(a, b, [](float x, float y) { return x == y; });
    }
    friend int ne(Float4 a, Float4 b) {
        return mask(a, b, [](float x, float y) { return x != y; });
    }

private:
    template <typename Op>
    static Float4 map(Float4 a, Float4 b, Op op) {
        Float4 r;
        for (int i = 0; i < 4; ++i)
            r.v_[i] = op(a.v_[i], b.v_[i]);
        return r;
    }
    template <typename Op>
    static int mask(Float4 a, Float4 b, Op op) {
        int m = 0;
        for (int i = 0; i < 4; ++i)
            m |= op(a.v_[i], b.v_[i]) ? 1 << i : 0;
        return m;
    }

    float v_[4];
#endif
};

}  // namespace lancer
