#include "materials/MipMap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace lancer {

namespace {

int halfSize(int n) {
    return std::max(1, n / 2);
}

struct Tap {
    int index;
    float weight;
};

// The source texels, along one axis of n texels, that make destination texel i of the next level
// (halfSize(n) texels), weighted by how much of the destination texel's area each one covers.
// Non-power-of-two sizes are filtered in place rather than resampled up to a power of two first,
// as pbrt does: level 0 then keeps the image's exact texels, with none of the blur and ringing
// (negative lobes, clamped) of the windowed-sinc upsampling, and no up to 4x larger pyramid. An
// odd n = 2m + 1 halves to m texels, each 2 + 1/m source texels wide, so three taps weighted
// (m - i, m, i + 1) / n: the exact box filter of its footprint, which keeps the image's mean.
std::array<Tap, 3> downsampleTaps(int n, int i) {
    if (n == 1) return {{{0, 1.0f}, {0, 0.0f}, {0, 0.0f}}};
    if (n % 2 == 0) return {{{2 * i, 0.5f}, {2 * i + 1, 0.5f}, {2 * i + 1, 0.0f}}};
    const int m = n / 2;
    const auto weight = [n](int w) { return static_cast<float>(w) / static_cast<float>(n); };
    return {{{2 * i, weight(m - i)}, {2 * i + 1, weight(m)}, {2 * i + 2, weight(i + 1)}}};
}

// One pass of the separable filter: the image halved along x (alongX) or along y.
Image halve(const Image& source, bool alongX) {
    const int n = alongX ? source.width() : source.height();
    Image result(alongX ? halfSize(n) : source.width(), alongX ? source.height() : halfSize(n));
    for (int y = 0; y < result.height(); ++y)
        for (int x = 0; x < result.width(); ++x) {
            Color sum;
            for (const Tap& tap : downsampleTaps(n, alongX ? x : y))
                sum += tap.weight * (alongX ? source.at(tap.index, y) : source.at(x, tap.index));
            result.at(x, y) = sum;
        }
    return result;
}

int wrap(int i, int n) {
    const int r = i % n;
    return r < 0 ? r + n : r;
}

// Repeat addressing of a texture coordinate, reduced to [0, 1] before it is scaled so that large
// coordinates keep their precision. A non-finite coordinate (a degenerate hit) reads as 0.
float wrapCoordinate(float u) {
    return std::isfinite(u) ? u - std::floor(u) : 0.0f;
}

}  // namespace

MipMap::MipMap(Image image) {
    levels_.push_back(std::move(image));
    while (levels_.back().width() > 1 || levels_.back().height() > 1)
        levels_.push_back(halve(halve(levels_.back(), true), false));
}

Color MipMap::texel(int level, int x, int y) const {
    const Image& picture = levels_[level];
    return picture.at(wrap(x, picture.width()), wrap(y, picture.height()));
}

Color MipMap::bilinear(int level, Vec2 uv) const {
    const Image& picture = levels_[level];
    // Continuous texel coordinates, with texel centres at integers.
    const float s = wrapCoordinate(uv.x) * static_cast<float>(picture.width()) - 0.5f;
    const float t = (1 - wrapCoordinate(uv.y)) * static_cast<float>(picture.height()) - 0.5f;
    const float x0 = std::floor(s), y0 = std::floor(t);
    const float fx = s - x0, fy = t - y0;
    const int x = static_cast<int>(x0), y = static_cast<int>(y0);
    return (1 - fy) * ((1 - fx) * texel(level, x, y) + fx * texel(level, x + 1, y)) +
           fy * ((1 - fx) * texel(level, x, y + 1) + fx * texel(level, x + 1, y + 1));
}

Color MipMap::trilinear(Vec2 uv, float width) const {
    const Image& base = levels_.front();
    const float resolution = static_cast<float>(std::max(base.width(), base.height()));
    const float level = std::log2(width * resolution);
    const int last = levelCount() - 1;
    if (!(level > 0)) return bilinear(0, uv);
    if (level >= static_cast<float>(last)) return bilinear(last, uv);
    const int below = static_cast<int>(level);
    const float blend = level - static_cast<float>(below);
    return (1 - blend) * bilinear(below, uv) + blend * bilinear(below + 1, uv);
}

}  // namespace lancer
