#include "geometry/Sphere.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lancer {

Sphere::Sphere(const Vec3& center, float radius, const Material* material)
    : Shape(material), center_(center), radius_(radius) {}

std::unique_ptr<Shape> Sphere::create(const Parameters& parameters, const Material* material) {
    return std::make_unique<Sphere>(parameters.point("center"),
                                    parameters.numberAbove("radius", 0, false), material);
}

Bounds3 Sphere::bounds() const {
    return {center_ - Vec3(radius_), center_ + Vec3(radius_)};
}

std::optional<std::pair<double, double>> Sphere::lineRoots(const Ray& ray, Roots wanted) const {
    // Solved in double precision: the roots, and so the side of the surface a spawned ray starts
    // on, are then exact to far below the float error bound used to offset spawned rays.
    const Vec3d o = Vec3d(ray.origin) - Vec3d(center_);
    const Vec3d d(ray.direction);
    const double r = radius_;
    const double a = dot(d, d);
    if (a == 0) return std::nullopt;
    // One division by a, started at once, instead of two in the chain of dependent steps that
    // bounds this function's speed.
    const double inverseA = 1 / a;
    const double halfB = dot(o, d);
    const double c = dot(o, o) - r * r;
    // From outside (c > 0), moving away (halfB > 0): the roots below are then both negative, by
    // their signs alone (q < 0, so q / a < 0 and c / q < 0). A ray leaving a sphere it was
    // spawned on meets it so, as does one pointing away from it: the division and the square
    // root on the chain below are then not waited for.
    if (wanted == Roots::ahead && c > 0 && halfB > 0) return std::nullopt;
    // b^2 - 4ac rewritten with the closest point of the line to the centre (Ray Tracing Gems,
    // ch. 7), which keeps its precision for small spheres far from the ray origin.
    const Vec3d toLine = o - (halfB * inverseA) * d;
    const double discriminant = a * (r * r - dot(toLine, toLine));
    if (discriminant < 0) return std::nullopt;
    const double q = -(halfB + std::copysign(std::sqrt(discriminant), halfB));
    const double t0 = q * inverseA;
    const double t1 = q != 0 ? c / q : t0;
    return std::pair{std::min(t0, t1), std::max(t0, t1)};
}

std::optional<SurfaceCrossing> Sphere::cross(const Ray& ray, float tMax) const {
    const std::optional<std::pair<double, double>> roots = lineRoots(ray, Roots::ahead);
    if (!roots) return std::nullopt;
    const auto [t0, t1] = *roots;
    if (t0 >= tMax || t1 <= 0) return std::nullopt;
    const double t = t0 > 0 ? t0 : t1;
    if (t >= tMax) return std::nullopt;
    return SurfaceCrossing{t, t};
}

void Sphere::crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const {
    const std::optional<std::pair<double, double>> roots = lineRoots(ray, Roots::ahead);
    if (!roots) return;
    for (const double t : {roots->first, roots->second})
        if (t > 0 && t < tMax) crossings.push_back(SurfaceCrossing{t, t});
}

void Sphere::crossLine(const Ray& ray, LineCrossings& crossings) const {
    const std::optional<std::pair<double, double>> roots = lineRoots(ray, Roots::all);
    if (!roots) return;
    crossings.push_back({SurfaceCrossing{roots->first, roots->first}, true});
    crossings.push_back({SurfaceCrossing{roots->second, roots->second}, false});
}

Hit Sphere::record(const Ray& ray, const SurfaceCrossing& crossing) const {
    const double t = crossing.tShape;
    const double r = radius_;
    // Project the point back onto the surface; what remains is the rounding to float.
    Vec3d local = Vec3d(ray.origin) - Vec3d(center_) + t * Vec3d(ray.direction);
    local *= r / length(local);
    const Vec3 p = Vec3(Vec3d(center_) + local);
    const Vec3 n = Vec3(local / r);

    Hit hit = Hit::atRoundedPoint(t, p, n);
    hit.deferUv(this, n);
    const float cosLatitude = std::sqrt(std::max(0.0f, n.x * n.x + n.z * n.z));
    // dp/du = 2 pi r (-cos lambda sin phi, 0, -cos lambda cos phi) = 2 pi r (n.z, 0, -n.x), and
    // dp/dv = pi r (-sin lambda cos phi, cos lambda, sin lambda sin phi): no trigonometry needed
    // but at the poles, where phi is 0.
    hit.dpdu = (2 * kPi * radius_) * Vec3(n.z, 0, -n.x);
    hit.dpdv = cosLatitude > 0 ? (kPi * radius_) * Vec3(-n.y * n.x / cosLatitude, cosLatitude,
                                                        -n.y * n.z / cosLatitude)
                               : (kPi * radius_) * Vec3(-n.y, 0, 0);
    hit.shape = this;
    hit.primitive = 0;
    hit.material = material();
    return hit;
}

// u = phi / 2 pi and v = 1/2 + lambda / pi for the longitude phi and latitude lambda of the unit
// normal n = (cos lambda cos phi, sin lambda, -cos lambda sin phi).
Vec2 Sphere::uvAt(const Vec3& n) const {
    float phi = std::atan2(-n.z, n.x);
    if (phi < 0) phi += 2 * kPi;
    return {phi / (2 * kPi), 0.5f + std::asin(clamp(n.y, -1.0f, 1.0f)) / kPi};
}

float Sphere::area(std::uint32_t) const {
    return 4 * kPi * radius_ * radius_;
}

std::optional<ShapeSample> Sphere::sample(std::uint32_t primitive, const Vec2& u) const {
    const double z = 1 - 2 * static_cast<double>(u.x);
    const double ring = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = 2 * std::numbers::pi * u.y;
    const Vec3d normal(ring * std::cos(phi), ring * std::sin(phi), z);
    return ShapeSample{Vec3(Vec3d(center_) + static_cast<double>(radius_) * normal), Vec3(normal),
                       1 / area(primitive)};
}

bool Sphere::containsOrTouches(const Vec3& p) const {
    const double reach = radius_ + 2 * length(Vec3d(gamma(3) * abs(p)));
    return lengthSquared(Vec3d(p) - Vec3d(center_)) <= reach * reach;
}

double Sphere::oneMinusCosConeAngle(const Vec3& p) const {
    const double r = radius_;
    const double sin2ThetaMax = r * r / lengthSquared(Vec3d(p) - Vec3d(center_));
    // 1 - cos written as sin^2 / (1 + cos): no cancellation for small, distant spheres.
    return sin2ThetaMax / (1 + std::sqrt(std::max(0.0, 1 - sin2ThetaMax)));
}

float Sphere::coneDensity(const Vec3& p) const {
    return static_cast<float>(1 / (2 * std::numbers::pi * oneMinusCosConeAngle(p)));
}

std::optional<DirectionSample> Sphere::sample(std::uint32_t primitive, const Vec3& reference,
                                              const Vec2& u) const {
    if (containsOrTouches(reference)) return Shape::sample(primitive, reference, u);

    // Uniform within the cone: 1 - cos(theta) uniform in [0, 1 - cos(theta_max)].
    const Vec3d center(center_);
    const double r = radius_;
    const Vec3d toCenter = center - Vec3d(reference);
    const Vec3d axis = normalize(toCenter);
    const double oneMinusCosTheta = u.x * oneMinusCosConeAngle(reference);
    const double cosTheta = 1 - oneMinusCosTheta;
    const double sinTheta = std::sqrt(std::max(0.0, oneMinusCosTheta * (2 - oneMinusCosTheta)));
    const double phi = 2 * std::numbers::pi * u.y;
    Vec3d a, b;
    coordinateSystem(axis, a, b);
    const Vec3d wi = cosTheta * axis + sinTheta * (std::cos(phi) * a + std::sin(phi) * b);
    // Where that direction enters the sphere; at the cone's edge rounding may make the ray graze
    // past it, so the discriminant is clamped to the tangent point.
    const double along = dot(wi, toCenter);
    const double offAxisSquared = lengthSquared(toCenter - along * wi);
    const double t = along - std::sqrt(std::max(0.0, r * r - offAxisSquared));
    const Vec3d onSphere = Vec3d(reference) + t * wi;
    return seenFrom(reference,
                    {Vec3(onSphere), Vec3(normalize(onSphere - center)), coneDensity(reference)});
}

float Sphere::pdf(std::uint32_t primitive, const Vec3& reference, const Vec3& wi,
                  const Hit& onSurface) const {
    if (containsOrTouches(reference)) return Shape::pdf(primitive, reference, wi, onSurface);
    return coneDensity(reference);
}

Tessellation Sphere::tessellate(const TessellationRequest& request) const {
    const auto piecesFor = [&](float length) {
        return std::clamp(static_cast<int>(std::ceil(length / request.patchSize)), 1, 4096);
    };
    const int columns = std::max(8, piecesFor(2 * kPi * radius_));
    const int rows = std::max(4, piecesFor(kPi * radius_));
    const auto at = [&](int row, int column) {
        const float theta = kPi * static_cast<float>(row) / static_cast<float>(rows);
        const float phi =
            2 * kPi * static_cast<float>(column % columns) / static_cast<float>(columns);
        return center_ + radius_ * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                        -std::sin(theta) * std::sin(phi));
    };
    Tessellation tessellation;
    // The deepest a chord sinks below the surface is about r (1 - cos(a / 2)) for the cell's
    // angular width a; the probe starts beyond twice the widest cell's, with a margin.
    const float widest = 2 * kPi / static_cast<float>(std::min(columns, 2 * rows));
    tessellation.curved = true;
    tessellation.probeDistance = 2 * radius_ * (1 - std::cos(widest)) + 1e-4f * radius_;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const Vec3 p00 = at(row, column), p01 = at(row, column + 1), p10 = at(row + 1, column),
                       p11 = at(row + 1, column + 1);
            // Counter-clockwise seen from outside: the outside is the sphere's front.
            if (row > 0) tessellation.facets.push_back({{p00, p10, p01}, 0});
            if (row < rows - 1) tessellation.facets.push_back({{p01, p10, p11}, 0});
        }
    return tessellation;
}

}  // namespace lancer
