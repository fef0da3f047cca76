#pragma once

namespace lancer {

// A 2-component vector: texture coordinates and sample points in [0,1)^2.
struct Vec2 {
    float x = 0, y = 0;

    constexpr Vec2() = default;
    constexpr Vec2(float x_, float y_) : x(x_), y(y_) {}

    constexpr Vec2 operator+(const Vec2& b) const { return {x + b.x, y + b.y}; }
    constexpr Vec2 operator-(const Vec2& b) const { return {x - b.x, y - b.y}; }
    constexpr Vec2 operator*(float s) const { return {x * s, y * s}; }
    constexpr bool operator==(const Vec2&) const = default;
};

constexpr Vec2 operator*(float s, const Vec2& v) {
    return v * s;
}

}  // namespace lancer
