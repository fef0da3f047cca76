#include "geometry/Cone.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/FlatRings.h"
#include "geometry/RevolutionUv.h"

namespace lancer {

Cone::Cone(const Vec3& base, float baseRadius, const Vec3& top, float topRadius, bool open,
           const Material* material)
    : Shape(material),
      base_(base),
      axis_(normalize(top - base)),
      height_(length(top - base)),
      baseRadius_(baseRadius),
      topRadius_(topRadius) {
    coordinateSystem(axis_, tangent_, bitangent_);
    if (dot(lancer::cross(tangent_, bitangent_), axis_) < 0) std::swap(tangent_, bitangent_);
    if (open) return;
    if (baseRadius_ > 0)
        caps_.push_back(std::make_unique<Disk>(base, -axis_, baseRadius_, 0, material));
    if (topRadius_ > 0)
        caps_.push_back(std::make_unique<Disk>(top, axis_, topRadius_, 0, material));
}

void Cone::checkAxis(const Parameters& parameters, const Vec3& base, const Vec3& top) {
    if (!(lengthSquared(top - base) > 0))
        parameters.fail("top", "\"top\" must differ from \"base\"");
}

std::unique_ptr<Shape> Cone::create(const Parameters& parameters, const Material* material) {
    const Vec3 base = parameters.point("base"), top = parameters.point("top");
    checkAxis(parameters, base, top);
    const float baseRadius = parameters.numberAbove("base_radius", 0, true);
    const float topRadius = parameters.numberAbove("top_radius", 0, true);
    if (baseRadius == 0 && topRadius == 0)
        parameters.fail("top_radius", "\"base_radius\" and \"top_radius\" cannot both be 0");
    const bool open = parameters.has("open") && parameters.flag("open");
    return std::make_unique<Cone>(base, baseRadius, top, topRadius, open, material);
}

Bounds3 Cone::bounds() const {
    // The convex hull of the two rims: along each axis a rim of radius r reaches r sqrt(1 - a^2)
    // from its centre.
    Bounds3 box;
    for (const auto& [z, r] : {std::pair{0.0f, baseRadius_}, {height_, topRadius_}}) {
        Vec3 reach;
        for (int axis = 0; axis < 3; ++axis)
            reach[axis] = r * std::sqrt(std::max(0.0f, 1 - axis_[axis] * axis_[axis]));
        const Vec3 center = base_ + z * axis_;
        box = merge(box, Bounds3(center - reach, center + reach));
    }
    // The intersection works in double: the surface it finds may lie a few ulps outside.
    const Vec3 slack = gamma(3) * max(abs(box.min), abs(box.max)) + gamma(3) * (box.max - box.min);
    return {box.min - slack, box.max + slack};
}

Cone::SideCrossings Cone::sideCrossings(const Ray& ray) const {
    // The side in double, in the frame of the axis: x^2 + y^2 = (r0 + k z)^2 for z in [0, h].
    const Vec3d o = Vec3d(ray.origin) - Vec3d(base_), d(ray.direction);
    const Vec3d t1(tangent_), t2(bitangent_), a(axis_);
    const double ox = dot(o, t1), oy = dot(o, t2), oz = dot(o, a);
    const double dx = dot(d, t1), dy = dot(d, t2), dz = dot(d, a);
    const double h = height_, k = (static_cast<double>(topRadius_) - baseRadius_) / h;
    const double radiusAtOrigin = baseRadius_ + k * oz;
    // f(t) = A t^2 + 2 B t + C, negative inside the side.
    const double A = dx * dx + dy * dy - k * k * dz * dz;
    const double B = ox * dx + oy * dy - k * dz * radiusAtOrigin;
    const double C = ox * ox + oy * oy - radiusAtOrigin * radiusAtOrigin;
    std::array<double, 2> roots{};
    int rootCount = 0;
    if (A == 0) {
        // Along a line of the cone's surface: one crossing at most.
        if (B != 0) roots[rootCount++] = -C / (2 * B);
    } else if (const double discriminant = B * B - A * C; discriminant >= 0) {
        const double q = -(B + std::copysign(std::sqrt(discriminant), B));
        roots[rootCount++] = q / A;
        roots[rootCount++] = q != 0 ? C / q : q / A;
        if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    }
    SideCrossings side;
    for (int i = 0; i < rootCount; ++i) {
        const double t = roots[static_cast<std::size_t>(i)];
        const double z = oz + t * dz;
        // f decreases where the line enters.
        if (z >= 0 && z <= h)
            side.crossings[side.count++] = {SurfaceCrossing{t, t, 0}, A * t + B < 0};
    }
    return side;
}

std::optional<SurfaceCrossing> Cone::cross(const Ray& ray, float tMax) const {
    std::optional<SurfaceCrossing> nearest;
    double tNearest = tMax;
    const SideCrossings side = sideCrossings(ray);
    for (int i = 0; i < side.count; ++i) {
        const SurfaceCrossing& c = side.crossings[static_cast<std::size_t>(i)].crossing;
        if (c.t > 0 && c.t < tNearest) {
            nearest = c;
            tNearest = c.t;
            break;
        }
    }
    for (std::size_t i = 0; i < caps_.size(); ++i)
        if (std::optional<SurfaceCrossing> cap =
                caps_[i]->cross(ray, static_cast<float>(std::min<double>(tNearest, tMax)));
            cap && cap->t < tNearest) {
            cap->primitive = static_cast<std::uint32_t>(1 + i);
            nearest = cap;
            tNearest = cap->t;
        }
    return nearest;
}

void Cone::crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const {
    const SideCrossings side = sideCrossings(ray);
    for (int i = 0; i < side.count; ++i) {
        const SurfaceCrossing& c = side.crossings[static_cast<std::size_t>(i)].crossing;
        if (c.t > 0 && c.t < tMax) crossings.push_back(c);
    }
    for (std::size_t i = 0; i < caps_.size(); ++i)
        if (std::optional<SurfaceCrossing> cap = caps_[i]->cross(ray, tMax)) {
            cap->primitive = static_cast<std::uint32_t>(1 + i);
            crossings.push_back(*cap);
        }
}

void Cone::crossLine(const Ray& ray, LineCrossings& crossings) const {
    const std::size_t first = crossings.size();
    const SideCrossings side = sideCrossings(ray);
    crossings.insert(crossings.end(), side.crossings.begin(), side.crossings.begin() + side.count);
    for (std::size_t i = 0; i < caps_.size(); ++i)
        if (std::optional<SurfaceCrossing> cap = caps_[i]->lineCrossing(ray)) {
            cap->primitive = static_cast<std::uint32_t>(1 + i);
            // The caps face out of the solid: along -axis at the base, +axis at the top.
            const bool entering = dot(ray.direction, caps_[i]->normal()) < 0;
            crossings.push_back({*cap, entering});
        }
    std::sort(
        crossings.begin() + static_cast<std::ptrdiff_t>(first), crossings.end(),
        [](const LineCrossing& a, const LineCrossing& b) { return a.crossing.t < b.crossing.t; });
}

Hit Cone::record(const Ray& ray, const SurfaceCrossing& crossing) const {
    if (crossing.primitive > 0) {
        SurfaceCrossing onCap = crossing;
        onCap.primitive = 0;
        Hit hit = caps_[crossing.primitive - 1]->record(ray, onCap);
        hit.shape = this;
        hit.primitive = crossing.primitive;
        return hit;
    }
    const double t = crossing.tShape;
    const Vec3d p = Vec3d(ray.origin) + t * Vec3d(ray.direction);
    const Vec3d local = p - Vec3d(base_);
    const Vec3d t1(tangent_), t2(bitangent_), a(axis_);
    const double x = dot(local, t1), y = dot(local, t2);
    const double z = std::clamp(dot(local, a), 0.0, static_cast<double>(height_));
    const double k = (static_cast<double>(topRadius_) - baseRadius_) / height_;
    // The gradient of x^2 + y^2 - (r0 + k z)^2, halved.
    const Vec3 n(normalize(x * t1 + y * t2 - (k * (baseRadius_ + k * z)) * a));
    Hit hit = Hit::atRoundedPoint(t, Vec3(p), n);
    hit.deferUv(this, Vec3(Vec3d(x, y, z / height_)));
    // p = base + r(v) (cos phi t1 + sin phi t2) + v h a, phi = 2 pi u (phi = 0 on the axis).
    const double r = std::hypot(x, y);
    const auto cosPhi = r > 0 ? static_cast<float>(x / r) : 1.0f,
               sinPhi = r > 0 ? static_cast<float>(y / r) : 0.0f;
    hit.dpdu = (2 * kPi) * Vec3(-y * t1 + x * t2);
    hit.dpdv =
        (topRadius_ - baseRadius_) * (cosPhi * tangent_ + sinPhi * bitangent_) + height_ * axis_;
    hit.shape = this;
    hit.primitive = 0;
    hit.material = material();
    return hit;
}

Vec2 Cone::uvAt(const Vec3& local) const {
    return revolutionUv(local);
}

float Cone::area(std::uint32_t primitive) const {
    if (primitive > 0) return caps_[primitive - 1]->area(0);
    const float dr = topRadius_ - baseRadius_;
    return kPi * (baseRadius_ + topRadius_) * std::sqrt(height_ * height_ + dr * dr);
}

Vec3 Cone::sidePoint(float phi, float z) const {
    return base_ + z * axis_ +
           radiusAt(z) * (std::cos(phi) * tangent_ + std::sin(phi) * bitangent_);
}

std::optional<ShapeSample> Cone::sample(std::uint32_t primitive, const Vec2& u) const {
    if (primitive > 0) return caps_[primitive - 1]->sample(0, u);
    // The side's area below height z grows as r(z)^2 - r0^2: r^2 uniform between r0^2 and r1^2
    // (z uniform when the radii are equal) is uniform by area.
    const float r0 = baseRadius_, r1 = topRadius_;
    const float z =
        r0 == r1 ? u.x * height_
                 : height_ * (std::sqrt(r0 * r0 + u.x * (r1 * r1 - r0 * r0)) - r0) / (r1 - r0);
    const float phi = 2 * kPi * u.y;
    const Vec3 radial = std::cos(phi) * tangent_ + std::sin(phi) * bitangent_;
    const Vec3 n = normalize(height_ * radial - (r1 - r0) * axis_);
    return ShapeSample{sidePoint(phi, std::clamp(z, 0.0f, height_)), n, 1 / area(0)};
}

Tessellation Cone::tessellate(const TessellationRequest& request) const {
    const auto piecesFor = [&](float length) {
        return std::clamp(static_cast<int>(std::ceil(length / request.patchSize)), 1, 4096);
    };
    const float largest = std::max(baseRadius_, topRadius_);
    const int segments = std::max(16, piecesFor(2 * kPi * largest));
    const float dr = topRadius_ - baseRadius_;
    const int rows = piecesFor(std::sqrt(height_ * height_ + dr * dr));
    // The rims' directions, shared by the side and the caps.
    std::vector<Vec3> directions(static_cast<std::size_t>(segments));
    for (int k = 0; k < segments; ++k) {
        const float phi = 2 * kPi * static_cast<float>(k) / static_cast<float>(segments);
        directions[static_cast<std::size_t>(k)] =
            std::cos(phi) * tangent_ + std::sin(phi) * bitangent_;
    }
    const auto center = [&](int row) {
        return row == rows
                   ? base_ + height_ * axis_
                   : base_ + (height_ * static_cast<float>(row) / static_cast<float>(rows)) * axis_;
    };
    const auto radius = [&](int row) {
        return row == 0 ? baseRadius_
               : row == rows
                   ? topRadius_
                   : baseRadius_ + dr * static_cast<float>(row) / static_cast<float>(rows);
    };
    const auto at = [&](int row, int k) {
        return center(row) + radius(row) * directions[static_cast<std::size_t>(k % segments)];
    };
    Tessellation tessellation;
    for (int row = 0; row < rows; ++row)
        for (int k = 0; k < segments; ++k) {
            // Counter-clockwise seen from outside (dpdu x dpdv points out); none of zero area
            // at an apex.
            if (radius(row) > 0)
                tessellation.facets.push_back(
                    {{at(row, k), at(row, k + 1), at(row + 1, k + 1)}, 0});
            if (radius(row + 1) > 0)
                tessellation.facets.push_back(
                    {{at(row, k), at(row + 1, k + 1), at(row + 1, k)}, 0});
        }
    // The caps: the base one turned the other way round, counter-clockwise about -axis.
    for (std::size_t i = 0; i < caps_.size(); ++i) {
        const bool isBase = i == 0 && baseRadius_ > 0;
        const int row = isBase ? 0 : rows;
        addFlatRings(
            center(row), radius(row), 0, segments, piecesFor(radius(row)),
            [&](int k) {
                return directions[static_cast<std::size_t>(isBase ? (segments - k) % segments : k)];
            },
            static_cast<std::uint32_t>(1 + i), tessellation.facets);
    }
    // Points on the side's chords are moved onto the surface: the widest chord's sagitta, with
    // a margin.
    tessellation.curved = true;
    tessellation.probeDistance = 2 * largest * (1 - std::cos(kPi / static_cast<float>(segments))) +
                                 1e-4f * std::max(largest, height_);
    return tessellation;
}

}  // namespace lancer
