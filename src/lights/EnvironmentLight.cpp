#include "lights/EnvironmentLight.h"

#include <algorithm>
#include <cmath>

#include "math/Float.h"

namespace lancer {

namespace {

// atan2(y, x) within 1e-7 radians (a float's spacing near pi is 2.4e-7) at a fraction of libm's
// cost: atan on [0, 1] as t P(t^2), P of degree 7 fitted to it, after reducing to the first
// octant.
float polynomialAtan2(float y, float x) {
    const float ax = std::abs(x), ay = std::abs(y);
    const float larger = std::max(ax, ay);
    if (larger == 0) return std::copysign(std::signbit(x) ? kPi : 0.0f, y);
    const float t = std::min(ax, ay) / larger, s = t * t;
    constexpr float kCoefficients[] = {-0.004054504f, 0.021862777f, -0.055912163f, 0.096421957f,
                                       -0.139086351f, 0.199465692f, -0.333298624f, 0.999999344f};
    float p = 0;
    for (const float c : kCoefficients)
        p = p * s + c;
    float angle = t * p;
    if (ay > ax) angle = kPi / 2 - angle;
    if (std::signbit(x)) angle = kPi - angle;
    return std::copysign(angle, y);
}

float rowSinTheta(int y, int h) {
    return std::sin(kPi * (static_cast<float>(y) + 0.5f) / static_cast<float>(h));
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

// The map scaled by `intensity`, with a border: a column on each side wrapped around from the
// other side, and the first and last rows repeated above and below.
std::vector<EnvironmentLight::Texel> EnvironmentLight::borderedTexels(const Image& map,
                                                                      float intensity) {
    const int w = map.width(), h = map.height();
    std::vector<Texel> texels;
    texels.reserve(static_cast<std::size_t>(w + 2) * static_cast<std::size_t>(h + 2));
    for (int y = -1; y <= h; ++y)
        for (int x = -1; x <= w; ++x) {
            const Color radiance = map.at((x + w) % w, std::clamp(y, 0, h - 1)) * intensity;
            texels.push_back({radiance, radiance.luminance()});
        }
    return texels;
}

EnvironmentLight::EnvironmentLight(Image map, float intensity, float rotateDegrees)
    : width_(map.width()),
      height_(map.height()),
      cosRotate_(std::cos(radians(rotateDegrees))),
      sinRotate_(std::sin(radians(rotateDegrees))),
      texels_(borderedTexels(map, intensity)),
      strategies_(strategies()) {
    // Each texel's cell subtends (2 pi / w) (pi / h) sin(theta) steradians.
    for (int y = 0; y < height_; ++y) {
        const float solidAngle = 2 * kPi * kPi * rowSinTheta(y, height_) /
                                 (static_cast<float>(width_) * static_cast<float>(height_));
        for (int x = 0; x < width_; ++x)
            radianceIntegral_ += texel(x, y) * solidAngle;
    }
}

// Each cell's luminance averaged over it as the bilinear lookup spreads it (weights 1/8, 3/4,
// 1/8 across and down: the exact cell average of the linear interpolation between texel
// centres, so that every cell the lookup sees light in has a mean above zero).
std::vector<float> EnvironmentLight::cellMeans() const {
    constexpr float kSpread[3] = {0.125f, 0.75f, 0.125f};
    std::vector<float> means;
    means.reserve(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            float mean = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    mean += kSpread[dy + 1] * kSpread[dx + 1] * luminance(x + dx, y + dy);
            means.push_back(std::max(mean, 0.0f));
        }
    return means;
}

EnvironmentLight::Strategies EnvironmentLight::strategies() const {
    const std::vector<float> means = cellMeans();
    return {wholeMap(means), aboveAverage(means)};
}

// A cell's weight is its mean luminance times sin(theta) at the row's centre, the area of the
// cell's image on the sphere. Within the cell the point follows the bilinear luminance Y, so the
// density is the cell's probability w / (N mean w) per cell area 1 / N, times Y over the cell's
// mean = w / sin(theta): Y sin(theta) / mean w, whatever the cell.
EnvironmentLight::Strategy EnvironmentLight::wholeMap(const std::vector<float>& means) const {
    std::vector<float> weights(means.size());
    for (int y = 0; y < height_; ++y) {
        const float sinTheta = rowSinTheta(y, height_);
        for (std::size_t i = cell(0, y); i < cell(width_, y); ++i)
            weights[i] = means[i] * sinTheta;
    }
    return strategy(weights, {});
}

// A cell's weight is its mean's excess over the map's mean luminance (over the sphere), times
// sin(theta); then the density is the whole map's with w = (mean - average) sin(theta), times the
// cell's share (mean - average) / mean of its mean.
EnvironmentLight::Strategy EnvironmentLight::aboveAverage(const std::vector<float>& means) const {
    double weighted = 0, area = 0;
    for (int y = 0; y < height_; ++y) {
        const double sinTheta = rowSinTheta(y, height_);
        for (std::size_t i = cell(0, y); i < cell(width_, y); ++i) {
            weighted += means[i] * sinTheta;
            area += sinTheta;
        }
    }
    const auto average = static_cast<float>(weighted / area);
    std::vector<float> weights(means.size()), share(means.size());
    bool anyAbove = false;
    for (int y = 0; y < height_; ++y) {
        const float sinTheta = rowSinTheta(y, height_);
        for (std::size_t i = cell(0, y); i < cell(width_, y); ++i) {
            const float excess = means[i] - average;
            if (!(excess > 0)) continue;
            anyAbove = true;
            weights[i] = excess * sinTheta;
            share[i] = excess / means[i];
        }
    }
    // A uniform map has no cell above its average: BSDF sampling is then as good, and the
    // whole map is sampled as it is alone.
    if (!anyAbove) return wholeMap(means);
    return strategy(weights, std::move(share));
}

EnvironmentLight::Strategy EnvironmentLight::strategy(const std::vector<float>& weights,
                                                      std::vector<float> cellShare) const {
    Strategy s{Distribution2D(weights, width_, height_), {}, std::move(cellShare)};
    for (int y = 0; y < height_; ++y)
        s.rowDensity.push_back(rowSinTheta(y, height_) / s.cells.integral());
    return s;
}

Vec2 EnvironmentLight::mapPoint(const Vec3& d) {
    const float u = 0.5f + polynomialAtan2(d.x, -d.z) / (2 * kPi);
    // acos(d.y), as the angle from +y to d: exact to the end at the poles, where acos is steep.
    const float v = polynomialAtan2(std::sqrt(d.x * d.x + d.z * d.z), d.y) / kPi;
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
    // Texel centres are at (i + 0.5) / w: the four texels around uv are within the border.
    const float x = uv.x * static_cast<float>(width_) - 0.5f;
    const float y = uv.y * static_cast<float>(height_) - 0.5f;
    const float x0 = std::floor(x), y0 = std::floor(y);
    const float fx = x - x0, fy = y - y0;
    const int ix = static_cast<int>(x0), iy = static_cast<int>(y0);
    return (1 - fy) * ((1 - fx) * texel(ix, iy) + fx * texel(ix + 1, iy)) +
           fy * ((1 - fx) * texel(ix, iy + 1) + fx * texel(ix + 1, iy + 1));
}

Color EnvironmentLight::radiance(const Vec3& d) const {
    return lookUp(mapPoint(toMap(normalize(d))));
}

EnvironmentLight::Arrival EnvironmentLight::arrival(const Vec3& d) const {
    return arrivalBy(strategies_.alone, d);
}

EnvironmentLight::Arrival EnvironmentLight::arrivalBesideBsdf(const Vec3& d) const {
    return arrivalBy(strategies_.besideBsdf, d);
}

EnvironmentLight::Arrival EnvironmentLight::arrivalBy(const Strategy& strategy,
                                                      const Vec3& d) const {
    const Vec3 inMap = toMap(normalize(d));
    const Vec2 uv = mapPoint(inMap);
    Arrival seen{lookUp(uv), 0.0f};
    const float sinTheta = std::sqrt(std::max(0.0f, 1 - inMap.y * inMap.y));
    if (sinTheta > 0)
        seen.pdf = solidAngleDensity(mapDensity(strategy, uv, seen.radiance), sinTheta);
    return seen;
}

// The cell of texel (x, y) is four quadrants, in each of which the lookup is one bilinear patch
// between the luminances at the 3 x 3 points of the cell (its corners, the mean of four texels;
// its edges' midpoints, of two; its centre, the texel): a quadrant is picked by its integral,
// then a point in it in proportion to its patch (a row by the patch's linear marginal, then a
// column by the linear conditional).
Vec2 EnvironmentLight::sampleInCell(int x, int y, Vec2 u) const {
    const float w = static_cast<float>(width_), h = static_cast<float>(height_);
    float across[3][3];  // the texels' luminances mixed down: at the rows of the 3 x 3 points
    for (int i = 0; i < 3; ++i) {
        const float above = luminance(x + i - 1, y - 1), centre = luminance(x + i - 1, y),
                    below = luminance(x + i - 1, y + 1);
        across[0][i] = 0.5f * (above + centre);
        across[1][i] = centre;
        across[2][i] = 0.5f * (centre + below);
    }
    float at[3][3];
    for (int j = 0; j < 3; ++j) {
        at[j][0] = 0.5f * (across[j][0] + across[j][1]);
        at[j][1] = across[j][1];
        at[j][2] = 0.5f * (across[j][1] + across[j][2]);
    }
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

float EnvironmentLight::mapDensity(const Strategy& strategy, const Vec2& uv,
                                   const Color& radiance) const {
    // A black map is sampled uniformly.
    if (!(strategy.cells.integral() > 0)) return 1;
    const int y = std::min(static_cast<int>(uv.y * static_cast<float>(height_)), height_ - 1);
    const float density = strategy.rowDensity[static_cast<std::size_t>(y)] * radiance.luminance();
    if (strategy.cellShare.empty()) return density;
    const int x = std::min(static_cast<int>(uv.x * static_cast<float>(width_)), width_ - 1);
    return density * strategy.cellShare[cell(x, y)];
}

float EnvironmentLight::solidAngleDensity(float mapDensity, float sinTheta) {
    // (u, v) -> direction stretches area by 2 pi * pi * sin(theta).
    return mapDensity / (2 * kPi * kPi * sinTheta);
}

LightSample EnvironmentLight::sample(const Vec3&, const Vec2& u) const {
    return sampleBy(strategies_.alone, u);
}

LightSample EnvironmentLight::sampleBesideBsdf(const Vec3&, const Vec2& u) const {
    return sampleBy(strategies_.besideBsdf, u);
}

LightSample EnvironmentLight::sampleBy(const Strategy& strategy, const Vec2& u) const {
    LightSample s;
    s.atInfinity = true;
    const Distribution2D::CellSample cell = strategy.cells.sampleCell(u);
    if (!(cell.probability > 0)) return s;
    const Vec2 uv = sampleInCell(cell.x, cell.y, cell.offset);
    const Color radiance = lookUp(uv);
    const float mapPdf = mapDensity(strategy, uv, radiance);
    const float sinTheta = std::sin(uv.y * kPi);
    if (!(mapPdf > 0) || !(sinTheta > 0)) return s;
    s.wi = toWorld(mapDirection(uv));
    s.pdf = solidAngleDensity(mapPdf, sinTheta);
    s.irradiance = radiance / s.pdf;
    return s;
}

float EnvironmentLight::pdf(const Vec3&, const Vec3& wi, const Hit&) const {
    return arrival(wi).pdf;
}

float EnvironmentLight::pdfBesideBsdf(const Vec3&, const Vec3& wi, const Hit&) const {
    return arrivalBesideBsdf(wi).pdf;
}

Color EnvironmentLight::power(float sceneRadius) const {
    return kPi * sceneRadius * sceneRadius * radianceIntegral_;
}

}  // namespace lancer
