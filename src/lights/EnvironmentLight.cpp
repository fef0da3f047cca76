#include "lights/EnvironmentLight.h"

#include <algorithm>
#include <cmath>

#include "math/Float.h"

namespace lancer {

namespace {

// The density over the map's texels: each texel's luminance averaged over its cell as the
// bilinear lookup spreads it (weights 1/8, 3/4, 1/8 across and down, the exact cell average of
// the linear interpolation between texel centres), so that every direction the lookup sees
// light in has a density above zero; times sin(theta) at the row's centre, the area of the
// cell's image on the sphere.
std::vector<float> samplingWeights(const Image& map) {
    const int w = map.width(), h = map.height();
    constexpr float kSpread[3] = {0.125f, 0.75f, 0.125f};
    std::vector<float> weights(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y) {
        const float sinTheta =
            std::sin(kPi * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
        for (int x = 0; x < w; ++x) {
            float average = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int ty = std::clamp(y + dy, 0, h - 1);
                    const int tx = (x + dx + w) % w;
                    average += kSpread[dy + 1] * kSpread[dx + 1] * map.at(tx, ty).luminance();
                }
            weights[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) +
                    static_cast<std::size_t>(x)] = std::max(average, 0.0f) * sinTheta;
        }
    }
    return weights;
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
    const float intensity =
        parameters.has("intensity") ? parameters.numberAbove("intensity", 0, true) : 1.0f;
    const float rotate = parameters.has("rotate") ? parameters.number("rotate") : 0.0f;
    return std::make_unique<EnvironmentLight>(std::move(map), intensity, rotate);
}

EnvironmentLight::EnvironmentLight(Image map, float intensity, float rotateDegrees)
    : map_(scaled(std::move(map), intensity)),
      cosRotate_(std::cos(radians(rotateDegrees))),
      sinRotate_(std::sin(radians(rotateDegrees))),
      distribution_(samplingWeights(map_), map_.width(), map_.height()) {
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

LightSample EnvironmentLight::sample(const Vec3&, const Vec2& u) const {
    LightSample s;
    s.atInfinity = true;
    float mapPdf = 0;
    const Vec2 uv = distribution_.sample(u, &mapPdf);
    const float sinTheta = std::sin(uv.y * kPi);
    if (!(mapPdf > 0) || !(sinTheta > 0)) return s;
    const Vec3 inMap = mapDirection(uv);
    s.wi = toWorld(inMap);
    // (u, v) -> direction stretches area by 2 pi * pi * sin(theta).
    s.pdf = mapPdf / (2 * kPi * kPi * sinTheta);
    s.irradiance = lookUp(uv) / s.pdf;
    return s;
}

float EnvironmentLight::pdf(const Vec3&, const Vec3& wi, const Hit&) const {
    const Vec3 inMap = toMap(normalize(wi));
    const float sinTheta = std::sqrt(std::max(0.0f, 1 - inMap.y * inMap.y));
    if (!(sinTheta > 0)) return 0;
    return distribution_.pdf(mapPoint(inMap)) / (2 * kPi * kPi * sinTheta);
}

Color EnvironmentLight::power(float sceneRadius) const {
    return kPi * sceneRadius * sceneRadius * radianceIntegral_;
}

}  // namespace lancer
