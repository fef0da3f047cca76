#include "geometry/Torus.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

namespace lancer {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// The root of f in [a, b], whose ends f has opposite signs at (negative at a when negativeAtA):
// Newton steps, kept inside the bracket that each value narrows, and bisection whenever a step
// would leave it (or the slope is useless), so that it converges whatever f looks like.
// f(x) returns {f(x), f'(x)}.
template <typename ValueAndSlope>
double bracketedRoot(const ValueAndSlope& f, double a, double b, bool negativeAtA) {
    double x = 0.5 * (a + b);
    for (int iteration = 0; iteration < 200; ++iteration) {
        const auto [value, slope] = f(x);
        if (value == 0) return x;
        if ((value < 0) == negativeAtA)
            a = x;
        else
            b = x;
        double next = x - value / slope;
        if (!(next > a && next < b)) next = 0.5 * (a + b);
        if (std::abs(next - x) <= 1e-15 * std::max(1.0, std::abs(x))) return next;
        x = next;
    }
    return x;
}

}  // namespace

Torus::Torus(const Vec3& center, const Vec3& axis, float majorRadius, float minorRadius,
             const Material* material)
    : Shape(material),
      center_(center),
      axis_(normalize(Vec3d(axis))),
      majorRadius_(majorRadius),
      minorRadius_(minorRadius) {
    // Built in double so that the frame is orthonormal to double precision: points go into it
    // by dot products and come out by the basis, and must land where they were.
    coordinateSystem(axis_, tangent_, bitangent_);
    if (dot(lancer::cross(tangent_, bitangent_), axis_) < 0) std::swap(tangent_, bitangent_);
}

std::unique_ptr<Shape> Torus::create(const Parameters& parameters, const Material* material) {
    const float majorRadius = parameters.numberAbove("major_radius", 0, false);
    const float minorRadius = parameters.numberAbove("minor_radius", 0, false);
    if (!(minorRadius < majorRadius))
        parameters.fail("minor_radius", "\"minor_radius\" must be less than \"major_radius\"");
    const Vec3 center = parameters.has("center") ? parameters.point("center") : Vec3(0);
    const Vec3 axis = parameters.has("axis") ? parameters.direction("axis") : Vec3(0, 1, 0);
    return std::make_unique<Torus>(center, axis, majorRadius, minorRadius, material);
}

Bounds3 Torus::bounds() const {
    // Along each axis the core circle reaches R sqrt(1 - a^2) from the centre, the tube r more.
    Vec3 reach;
    for (int i = 0; i < 3; ++i)
        reach[i] = static_cast<float>(
            majorRadius_ * std::sqrt(std::max(0.0, 1 - axis_[i] * axis_[i])) + minorRadius_);
    const Vec3 center(center_);
    const Bounds3 box(center - reach, center + reach);
    // The intersection works in double: the surface it finds may lie a few ulps outside.
    const Vec3 slack = gamma(3) * max(abs(box.min), abs(box.max)) + gamma(3) * (box.max - box.min);
    return {box.min - slack, box.max + slack};
}

template <typename Visit>
void Torus::visitCrossings(const Ray& ray, double tFrom, double tTo, Visit&& visit) const {
    // In the torus's frame scaled by 1 / (R + r), so that the torus fits in the unit sphere
    // whatever its size, along the unit direction: s = t |d| / (R + r).
    const double scale = static_cast<double>(majorRadius_) + minorRadius_;
    const double R = majorRadius_ / scale, r = minorRadius_ / scale;
    const Vec3d fromCenter = Vec3d(ray.origin) - center_, d(ray.direction);
    const double speed = length(d);
    if (!(speed > 0)) return;
    const Vec3d origin =
        Vec3d(dot(fromCenter, tangent_), dot(fromCenter, bitangent_), dot(fromCenter, axis_)) /
        scale;
    const Vec3d direction = Vec3d(dot(d, tangent_), dot(d, bitangent_), dot(d, axis_)) / speed;

    // Only the part of the ray within a sphere a little larger than the unit one, and within
    // the slab |z| <= r of the same margin, can meet the torus; the margin covers the rounding
    // of their ends for origins far away.
    constexpr double kMargin = 0.01;
    const double along = dot(origin, direction);
    const double offLineSquared = lengthSquared(origin - along * direction);
    const double reach = 1 + kMargin;
    if (offLineSquared >= reach * reach) return;
    const double halfChord = std::sqrt(reach * reach - offLineSquared);
    double sStart = std::max(tFrom * speed / scale, -along - halfChord);
    double sEnd = std::min(-along + halfChord, tTo * speed / scale);
    const double halfThickness = r + kMargin;
    if (direction.z != 0) {
        const double s0 = (-halfThickness - origin.z) / direction.z,
                     s1 = (halfThickness - origin.z) / direction.z;
        sStart = std::max(sStart, std::min(s0, s1));
        sEnd = std::min(sEnd, std::max(s0, s1));
    } else if (std::abs(origin.z) > halfThickness) {
        return;
    }
    if (!(sStart < sEnd)) return;

    // The quartic's coefficients from an origin moved to where the ray enters that sphere: of
    // order one, they keep their precision however far the ray started.
    const Vec3d o = origin + sStart * direction;
    const double span = sEnd - sStart;
    // F(s) = (s^2 + 2 b s + k)^2 - 4 R^2 (A s^2 + 2 B s + C) = s^4 + c3 s^3 + c2 s^2 + c1 s + c0;
    // c0 is not needed: the signs of F come from the distance below.
    const double b = dot(o, direction), k = lengthSquared(o) + R * R - r * r;
    const double A = direction.x * direction.x + direction.y * direction.y;
    const double B = o.x * direction.x + o.y * direction.y;
    const double fourR2 = 4 * R * R;
    const double c3 = 4 * b, c2 = 4 * b * b + 2 * k - fourR2 * A, c1 = 4 * b * k - 2 * fourR2 * B;

    // F has at most one root between consecutive roots of F' (where it is monotone), and F' at
    // most one between consecutive roots of F'' = 12 s^2 + 6 c3 s + 2 c2, a quadratic: each root
    // is then bracketed and found by bracketedRoot, none is lost to a wrong guess.
    std::array<double, 4> slopeBreaks{};
    int slopeBreakCount = 0;
    slopeBreaks[static_cast<std::size_t>(slopeBreakCount++)] = 0;
    if (const double discriminant = 9 * c3 * c3 - 24 * c2; discriminant > 0) {
        const double q = -0.5 * (3 * c3 + std::copysign(std::sqrt(discriminant), c3));
        std::array<double, 2> inflections{q / 6, q != 0 ? c2 / q : q / 6};
        std::sort(inflections.begin(), inflections.end());
        for (const double s : inflections)
            if (s > 0 && s < span) slopeBreaks[static_cast<std::size_t>(slopeBreakCount++)] = s;
    }
    slopeBreaks[static_cast<std::size_t>(slopeBreakCount++)] = span;
    const auto slopeAndCurvature = [&](double s) {
        return std::pair{((4 * s + 3 * c3) * s + 2 * c2) * s + c1, (12 * s + 6 * c3) * s + 2 * c2};
    };

    std::array<double, 5> monotoneBreaks{};
    int monotoneBreakCount = 0;
    monotoneBreaks[static_cast<std::size_t>(monotoneBreakCount++)] = 0;
    double slopeBefore = slopeAndCurvature(0).first;
    for (int i = 1; i < slopeBreakCount; ++i) {
        const double s = slopeBreaks[static_cast<std::size_t>(i)];
        const double slope = slopeAndCurvature(s).first;
        // F' changes sign in the piece, or is 0 at its end (where F may turn).
        if (slope == 0 || (slopeBefore != 0 && (slopeBefore < 0) != (slope < 0)))
            monotoneBreaks[static_cast<std::size_t>(monotoneBreakCount++)] =
                slope == 0
                    ? s
                    : bracketedRoot(slopeAndCurvature, slopeBreaks[static_cast<std::size_t>(i - 1)],
                                    s, slopeBefore < 0);
        slopeBefore = slope;
    }
    if (monotoneBreaks[static_cast<std::size_t>(monotoneBreakCount - 1)] < span)
        monotoneBreaks[static_cast<std::size_t>(monotoneBreakCount++)] = span;

    // The root itself from the signed distance to the tube, which has the quartic's roots and
    // sign (the quartic is (D^2 - r^2) times a positive factor) but stays well-conditioned near
    // the surface, where the quartic's terms cancel.
    const auto distanceAndSlope = [&](double s) {
        const Vec3d p = o + s * direction;
        // (Of order one here: no need for hypot's care against overflow, nor its cost.)
        const double rho = std::sqrt(p.x * p.x + p.y * p.y);
        const double D = std::sqrt((rho - R) * (rho - R) + p.z * p.z);
        // NaN on the axis or the core circle, where bracketedRoot bisects instead.
        const double slope =
            ((rho - R) * (p.x * direction.x + p.y * direction.y) / rho + p.z * direction.z) / D;
        return std::pair{D - r, slope};
    };
    double distanceBefore = distanceAndSlope(0).first;
    for (int i = 1; i < monotoneBreakCount; ++i) {
        const double s = monotoneBreaks[static_cast<std::size_t>(i)];
        const double distance = distanceAndSlope(s).first;
        // From a start on the surface itself, the ray leaves it there: the next crossing counts.
        if (distanceBefore != 0 && (distance == 0 || (distanceBefore < 0) != (distance < 0))) {
            const double root = distance == 0
                                    ? s
                                    : bracketedRoot(distanceAndSlope,
                                                    monotoneBreaks[static_cast<std::size_t>(i - 1)],
                                                    s, distanceBefore < 0);
            // Entering where the distance to the tube falls through r.
            if (visit((sStart + root) * scale / speed, distanceBefore > 0)) return;
        }
        distanceBefore = distance;
    }
}

std::optional<SurfaceCrossing> Torus::cross(const Ray& ray, float tMax) const {
    std::optional<SurfaceCrossing> nearest;
    // The first root from t = 0 on is the crossing, if it comes before tMax.
    visitCrossings(ray, 0, tMax, [&](double t, bool) {
        if (t > 0 && t < tMax) nearest = SurfaceCrossing{t, t, 0};
        return true;
    });
    return nearest;
}

void Torus::crossSegment(const Ray& ray, float tMax, SurfaceCrossings& crossings) const {
    visitCrossings(ray, 0, tMax, [&](double t, bool) {
        if (t > 0 && t < tMax) crossings.push_back(SurfaceCrossing{t, t, 0});
        return false;
    });
}

void Torus::crossLine(const Ray& ray, LineCrossings& crossings) const {
    constexpr double kWholeLine = std::numeric_limits<double>::infinity();
    visitCrossings(ray, -kWholeLine, kWholeLine, [&](double t, bool entering) {
        crossings.push_back({SurfaceCrossing{t, t, 0}, entering});
        return false;
    });
}

Vec3d Torus::pointAt(double phi, double theta) const {
    const double ring = majorRadius_ + minorRadius_ * std::cos(theta);
    return center_ + ring * (std::cos(phi) * tangent_ + std::sin(phi) * bitangent_) +
           (minorRadius_ * std::sin(theta)) * axis_;
}

Vec3d Torus::normalAt(double phi, double theta) const {
    return std::cos(theta) * (std::cos(phi) * tangent_ + std::sin(phi) * bitangent_) +
           std::sin(theta) * axis_;
}

Hit Torus::record(const Ray& ray, const SurfaceCrossing& crossing) const {
    const double t = crossing.tShape;
    const double R = majorRadius_, r = minorRadius_;
    const Vec3d fromCenter = Vec3d(ray.origin) + t * Vec3d(ray.direction) - center_;
    const double x = dot(fromCenter, tangent_), y = dot(fromCenter, bitangent_),
                 z = dot(fromCenter, axis_);
    // The point projected onto the surface along the tube's radius (a crossing is never on the
    // axis nor on the core circle); what remains is the rounding to float.
    const double rho = std::hypot(x, y);
    const double cosPhi = x / rho, sinPhi = y / rho;
    const double D = std::hypot(rho - R, z);
    const double cosTheta = (rho - R) / D, sinTheta = z / D;
    const Vec3d radial = cosPhi * tangent_ + sinPhi * bitangent_;
    const double ring = R + r * cosTheta;
    const Vec3d p = center_ + ring * radial + (r * sinTheta) * axis_;
    const Vec3d n = cosTheta * radial + sinTheta * axis_;

    Hit hit = Hit::atRoundedPoint(t, Vec3(p), Vec3(normalize(n)));
    double phi = std::atan2(y, x);
    if (phi < 0) phi += kTwoPi;
    double theta = std::atan2(z, rho - R);
    if (theta < 0) theta += kTwoPi;
    hit.setUv({static_cast<float>(phi / kTwoPi), static_cast<float>(theta / kTwoPi)});
    // dp/dphi = (R + r cos theta) (-sin phi t1 + cos phi t2), dp/dtheta = r (-sin theta radial +
    // cos theta axis), times 2 pi for u and v.
    hit.dpdu = Vec3((kTwoPi * ring) * (cosPhi * bitangent_ - sinPhi * tangent_));
    hit.dpdv = Vec3((kTwoPi * r) * (cosTheta * axis_ - sinTheta * radial));
    hit.shape = this;
    hit.primitive = 0;
    hit.material = material();
    return hit;
}

float Torus::area(std::uint32_t) const {
    return 4 * kPi * kPi * majorRadius_ * minorRadius_;
}

std::optional<ShapeSample> Torus::sample(std::uint32_t primitive, const Vec2& u) const {
    // The area element is (R + r cos theta) r dphi dtheta: phi is uniform, and theta has the
    // cumulative distribution (theta + (r / R) sin theta) / 2 pi, increasing (r < R), which is
    // inverted by bracketedRoot.
    const double ratio = static_cast<double>(minorRadius_) / majorRadius_;
    const double target = kTwoPi * u.x;
    const double theta = bracketedRoot(
        [&](double th) {
            return std::pair{th + ratio * std::sin(th) - target, 1 + ratio * std::cos(th)};
        },
        0, kTwoPi, true);
    const double phi = kTwoPi * u.y;
    return ShapeSample{Vec3(pointAt(phi, theta)), Vec3(normalAt(phi, theta)), 1 / area(primitive)};
}

int Torus::segmentsWithin(double radius, double depth) {
    const double angle = std::acos(std::max(-1.0, 1 - depth / radius));
    return static_cast<int>(std::ceil(kTwoPi / angle));
}

Tessellation Torus::tessellate(const TessellationRequest& request) const {
    const auto piecesFor = [&](float length) {
        return static_cast<int>(std::ceil(length / request.patchSize));
    };
    const float R = majorRadius_, r = minorRadius_;
    // The probe that moves a point onto the surface starts probeDistance off the facet and runs
    // twice that far: below 2 (R - r) it stays in the hole from the inner wall, below 2 r in the
    // tube. Each direction's term of it is kept within a quarter of the narrower of r, R - r.
    const double depth = std::min(r, R - r) / 4.0;
    const int columns = std::clamp(
        std::max({16, piecesFor(2 * kPi * (R + r)), segmentsWithin(R + r, depth)}), 1, 4096);
    const int rows =
        std::clamp(std::max({8, piecesFor(2 * kPi * r), segmentsWithin(r, depth)}), 1, 4096);
    const auto at = [&](int column, int row) {
        // Indices taken round the seams, so that both sides share the vertices bit for bit.
        return Vec3(pointAt(kTwoPi * (column % columns) / columns, kTwoPi * (row % rows) / rows));
    };
    Tessellation tessellation;
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            // Counter-clockwise seen from outside: dpdu x dpdv points out.
            tessellation.facets.push_back(
                {{at(column, row), at(column + 1, row), at(column + 1, row + 1)}, 0});
            tessellation.facets.push_back(
                {{at(column, row), at(column + 1, row + 1), at(column, row + 1)}, 0});
        }
    // The deepest a cell's chord strays from the surface is about the sum of the sagittas
    // radius (1 - cos(a / 2)) across it; as for the sphere, the probe starts beyond twice
    // radius (1 - cos a) of each direction, with a margin.
    tessellation.curved = true;
    tessellation.probeDistance = static_cast<float>(
        2 * ((R + r) * (1 - std::cos(kTwoPi / columns)) + r * (1 - std::cos(kTwoPi / rows))) +
        1e-4 * (R + r));
    return tessellation;
}

}  // namespace lancer
