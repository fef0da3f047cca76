#include "lights/EnvironmentLight.h"

#include <algorithm>
#include <cmath>

#include "math/Float.h"

namespace lancer {

namespace {

// Each texel's luminance averaged over its cell as the bilinear lookup spreads it (weights 1/8,
// 3/4, 1/8 across and down: the exact cell average of the linear interpolation between texel
// centres), so that every cell the lookup sees light in has a weight above zero.
std::vector<float> cellAverages(const Image& map) {
    const int w = map.width(), h = map.height();
    constexpr float kSpread[3] = {0.125f, 0.75f, 0.125f};
    std::vector<float> averages(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float average = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int ty = std::clamp(y + dy, 0, h - 1);
                    const int tx = (x + dx + w) % w;
                    average += kSpread[dy + 1] * kSpread[dx + 1] * map.at(tx, ty).luminance();
                }
            averages[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                     static_cast<std::size_t>(x)] = std::max(average, 0.0f);
        }
    return averages;
}

// The cells' weights: their average luminance times sin(theta) at the row's centre, the area of
// the cell's image on the sphere.
std::vector<float> samplingWeights(std::vector<float> averages, int w, int h) {
    for (int y = 0; y < h; ++y) {
        const float sinTheta =
            std::sin(kPi * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
        for (int x = 0; x < w; ++x)
            averages[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                     static_cast<std::size_t>(x)] *= sinTheta;
    }
    return averages;
}

// A point of [0, 1) distributed with a density proportional to the linear function from a at 0
// to b at 1 (pbrt-v4's SampleLinear), from u in [0, 1).
float sampleLinear(float u, float a, float b) {
    if (!(a + b > 0)) return u;
    if (u == 0 && a == 0) return 0;
    const float x = u * (a + b) / (a + std::sqrt((1 - u) * a * a + u * b * b));
    return std::min(x, kOneMinusEpsilon);
}

// Which of two parts, of weights first and second, holds u in [0, 1), and u rescaled within it.
bool pickSecond(float& u, float first, float second) {
    const float total = first + second;
    if (u * total < first) {
        u = std::min(u * total / first, kOneMinusEpsilon);
        return false;
    }
    u = second > 0 ? std::min((u * total - first) / second, kOneMinusEpsilon) : 0.0f;
    return true;
}

Image scaled(Image map, float intensity) {
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x)
            map.at(x, y) *= intensity;
    return map;
}

}  // namespace

std::unique_ptr<EnvironmentLight> EnvironmentLight::create(const Parameters& parameters,
                                                           Image map) {
    // A negative texel would make the sampling density negative and subtract light; a non-finite
    // one would spoil every pixel that sees or samples it.
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x) {
            const Color& c = map.at(x, y);
            if (!c.isFinite() || c.r < 0 || c.g < 0 || c.b < 0)
                parameters.fail("file", "the environment map's texel (" + std::to_string(x) + ", " +
                                            std::to_string(y) +
                                            ") is not a finite, non-negative colour");
        }
    const float intensity =
        parameters.has("intensity") ? parameters.numberAbove("intensity", 0, true) : 1.0f;
    const float rotate = parameters.has("rotate") ? parameters.number("rotate") : 0.0f;
    return std::make_unique<EnvironmentLight>(std::move(map), intensity, rotate);
}

EnvironmentLight::EnvironmentLight(Image map, float intensity, float rotateDegrees)
    : map_(scaled(std::move(map), intensity)),
      cosRotate_(std::cos(radians(rotateDegrees))),
      sinRotate_(std::sin(radians(rotateDegrees))),
      cellAverage_(cellAverages(map_)),
      distribution_(samplingWeights(cellAverage_, map_.width(), map_.height()), map_.width(),
                    map_.height()) {
    // Each texel's cell subtends (2 pi / w) (pi / h) sin(theta) steradians.
    const int w = map_.width(), h = map_.height();
    for (int y = 0; y < h; ++y) {
        const float sinTheta =
            std::sin(kPi * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
        const float solidAngle =
            2 * kPi * kPi * sinTheta / (static_cast<float>(w) * static_cast<float>(h));
        for (int x = 0; x < w; ++x)
            radianceIntegral_ += map_.at(x, y) * solidAngle;
    }
}

Vec2 EnvironmentLight::mapPoint(const Vec3& d) {
    const float u = 0.5f + std::atan2(d.x, -d.z) / (2 * kPi);
    const float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
    return {std::clamp(u, 0.0f, kOneMinusEpsilon), std::clamp(v, 0.0f, kOneMinusEpsilon)};
}

Vec3 EnvironmentLight::mapDirection(const Vec2& uv) {
    const float phi = (uv.x - 0.5f) * 2 * kPi;
    const float theta = uv.y * kPi;
    const float sinTheta = std::sin(theta);
    return {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
}

// The map turned by +rotate about y: a world direction is turned back by -rotate to find it.
Vec3 EnvironmentLight::toMap(const Vec3& world) const {
    return {cosRotate_ * world.x - sinRotate_ * world.z, world.y,
            sinRotate_ * world.x + cosRotate_ * world.z};
}

Vec3 EnvironmentLight::toWorld(const Vec3& map) const {
    return {cosRotate_ * map.x + sinRotate_ * map.z, map.y,
            -sinRotate_ * map.x + cosRotate_ * map.z};
}

Color EnvironmentLight::lookUp(const Vec2& uv) const {
    const int w = map_.width(), h = map_.height();
    // Texel centres are at (i + 0.5) / w.
    const float x = uv.x * static_cast<float>(w) - 0.5f;
    const float y = uv.y * static_cast<float>(h) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    const auto texel = [&](int tx, int ty) {
        return map_.at(((tx % w) + w) % w, std::clamp(ty, 0, h - 1));
    };
    return (1 - fy) * ((1 - fx) * texel(ix, iy) + fx * texel(ix + 1, iy)) +
           fy * ((1 - fx) * texel(ix, iy + 1) + fx * texel(ix + 1, iy + 1));
}

Color EnvironmentLight::radiance(const Vec3& d) const {
    return lookUp(mapPoint(toMap(normalize(d))));
}

// The cell of texel (x, y) is four quadrants, in each of which the lookup is one bilinear patch
// between the luminances at the 3 x 3 points of the cell (its corners, its edges' midpoints and
// its centre): a quadrant is picked by its integral, then a point in it in proportion to its
// patch (a row by the patch's linear marginal, then a column by the linear conditional).
Vec2 EnvironmentLight::sampleInCell(int x, int y, Vec2 u) const {
    const float w = static_cast<float>(map_.width()), h = static_cast<float>(map_.height());
    float at[3][3];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            at[j][i] = lookUp(Vec2((static_cast<float>(x) + 0.5f * static_cast<float>(i)) / w,
                                   (static_cast<float>(y) + 0.5f * static_cast<float>(j)) / h))
                           .luminance();
    const auto quadrant = [&](int j, int i) {
        return at[j][i] + at[j][i + 1] + at[j + 1][i] + at[j + 1][i + 1];
    };
    if (!(quadrant(0, 0) + quadrant(0, 1) + quadrant(1, 0) + quadrant(1, 1) > 0))
        return {(static_cast<float>(x) + u.x) / w, (static_cast<float>(y) + u.y) / h};
    const int j =
        pickSecond(u.y, quadrant(0, 0) + quadrant(0, 1), quadrant(1, 0) + quadrant(1, 1)) ? 1 : 0;
    const int i = pickSecond(u.x, quadrant(j, 0), quadrant(j, 1)) ? 1 : 0;
    const float a = at[j][i], b = at[j][i + 1], c = at[j + 1][i], d = at[j + 1][i + 1];
    const float t = sampleLinear(u.y, a + b, c + d);
    const float s = sampleLinear(u.x, (1 - t) * a + t * c, (1 - t) * b + t * d);
    return {std::min((static_cast<float>(x) + 0.5f * (static_cast<float>(i) + s)) / w,
                     kOneMinusEpsilon),
            std::min((static_cast<float>(y) + 0.5f * (static_cast<float>(j) + t)) / h,
                     kOneMinusEpsilon)};
}

float EnvironmentLight::mapDensity(const Vec2& uv) const {
    const int w = map_.width(), h = map_.height();
    const int x = std::min(static_cast<int>(uv.x * static_cast<float>(w)), w - 1);
    const int y = std::min(static_cast<int>(uv.y * static_cast<float>(h)), h - 1);
    const float average = cellAverage_[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                                       static_cast<std::size_t>(x)];
    const float cellDensity = distribution_.pdf(uv);
    // A cell without light is sampled (uniformly) only when the whole map is black.
    return average > 0 ? cellDensity * lookUp(uv).luminance() / average : cellDensity;
}

LightSample EnvironmentLight::sample(const Vec3&, const Vec2& u) const {
    LightSample s;
    s.atInfinity = true;
    float cellPdf = 0;
    const Vec2 inCell = distribution_.sample(u, &cellPdf);
    if (!(cellPdf > 0)) return s;
    // The point's offset within its cell is uniform, whichever cell: it places the point.
    const float w = static_cast<float>(map_.width()), h = static_cast<float>(map_.height());
    const int x = std::min(static_cast<int>(inCell.x * w), map_.width() - 1);
    const int y = std::min(static_cast<int>(inCell.y * h), map_.height() - 1);
    const Vec2 offset(std::clamp(inCell.x * w - static_cast<float>(x), 0.0f, kOneMinusEpsilon),
                      std::clamp(inCell.y * h - static_cast<float>(y), 0.0f, kOneMinusEpsilon));
    const Vec2 uv = sampleInCell(x, y, offset);
    const float mapPdf = mapDensity(uv);
    const float sinTheta = std::sin(uv.y * kPi);
    if (!(mapPdf > 0) || !(sinTheta > 0)) return s;
    s.wi = toWorld(mapDirection(uv));
    // (u, v) -> direction stretches area by 2 pi * pi * sin(theta).
    s.pdf = mapPdf / (2 * kPi * kPi * sinTheta);
    s.irradiance = lookUp(uv) / s.pdf;
    return s;
}

float EnvironmentLight::pdf(const Vec3&, const Vec3& wi, const Hit&) const {
    const Vec3 inMap = toMap(normalize(wi));
    const float sinTheta = std::sqrt(std::max(0.0f, 1 - inMap.y * inMap.y));
    if (!(sinTheta > 0)) return 0;
    return mapDensity(mapPoint(inMap)) / (2 * kPi * kPi * sinTheta);
}

Color EnvironmentLight::power(float sceneRadius) const {
    return kPi * sceneRadius * sceneRadius * radianceIntegral_;
}

}  // namespace lancer
