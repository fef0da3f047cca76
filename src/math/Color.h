#pragma once

#include <algorithm>
#include <cmath>

namespace lancer {

// Linear RGB radiance, irradiance or reflectance.
struct Color {
    float r = 0, g = 0, b = 0;

    constexpr Color() = default;
    constexpr Color(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit Color(float v) : r(v), g(v), b(v) {}

    constexpr Color& operator+=(const Color& c) {
        r += c.r;
        g += c.g;
        b += c.b;
        return *this;
    }
    constexpr Color& operator*=(const Color& c) {
        r *= c.r;
        g *= c.g;
        b *= c.b;
        return *this;
    }
    constexpr Color& operator*=(float s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    constexpr Color& operator/=(float s) { return *this *= 1.0f / s; }

    constexpr bool isBlack() const { return r == 0 && g == 0 && b == 0; }
    constexpr float maxComponent() const { return std::max(r, std::max(g, b)); }
    constexpr float average() const { return (r + g + b) / 3.0f; }
    // Rec. 709 luminance Y: how bright the colour looks (what environment maps are sampled by).
    constexpr float luminance() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
    bool isFinite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }

    constexpr bool operator==(const Color&) const = default;
};

constexpr Color operator+(Color a, const Color& b) {
    return a += b;
}
constexpr Color operator-(const Color& a, const Color& b) {
    return {a.r - b.r, a.g - b.g, a.b - b.b};
}
constexpr Color operator*(Color a, const Color& b) {
    return a *= b;
}
constexpr Color operator*(Color a, float s) {
    return a *= s;
}
constexpr Color operator*(float s, Color a) {
    return a *= s;
}
constexpr Color operator/(Color a, float s) {
    return a /= s;
}

}  // namespace lancer
