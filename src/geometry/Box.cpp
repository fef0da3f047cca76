#include "geometry/Box.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lancer {

Box::Box(const Vec3& min, const Vec3& max, const Material* material)
    : Shape(material), min_(min), max_(max) {}

std::unique_ptr<Shape> Box::create(const Parameters& parameters, const Material* material) {
    const Vec3 min = parameters.point("min"), max = parameters.point("max");
    if (!(min.x < max.x && min.y < max.y && min.z < max.z))
        parameters.fail("max", "\"max\" must be greater than \"min\" on every axis");
    return std::make_unique<Box>(min, max, material);
}

Box::Face Box::face(std::uint32_t index) const {
    const int axis = static_cast<int>(index / 2);
    const bool atMax = index % 2 == 1;
    const int next = (axis + 1) % 3, afterNext = (axis + 2) % 3;
    Face f{axis, atMax ? next : afterNext, atMax ? afterNext : next,
           atMax ? max_[axis] : min_[axis], Vec3(0)};
    f.normal[axis] = atMax ? 1.0f : -1.0f;
    return f;
}

Vec3 Box::pointAt(const Face& f, float u, float v) const {
    Vec3 p;
    p[f.axis] = f.position;
    p[f.uAxis] = min_[f.uAxis] + u * (max_[f.uAxis] - min_[f.uAxis]);
    p[f.vAxis] = min_[f.vAxis] + v * (max_[f.vAxis] - min_[f.vAxis]);
    return p;
}

std::optional<Box::LineSpan> Box::lineSpan(const Ray& ray) const {
    // The slabs in double: where the ray enters the box (the last slab entered) and leaves it
    // (the first slab left), and by which faces.
    LineSpan span{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                  0, 0};
    for (int axis = 0; axis < 3; ++axis) {
        const double o = ray.origin[axis], d = ray.direction[axis];
        const double lo = min_[axis], hi = max_[axis];
        if (d == 0) {
            // Parallel to the slab: inside it all along, or never.
            if (o < lo || o > hi) return std::nullopt;
            continue;
        }
        double tNear = (lo - o) / d, tFar = (hi - o) / d;
        std::uint32_t nearFace = 2 * static_cast<std::uint32_t>(axis), farFace = nearFace + 1;
        if (tNear > tFar) {
            std::swap(tNear, tFar);
            std::swap(nearFace, farFace);
        }
        if (tNear > span.tEnter) {
            span.tEnter = tNear;
            span.enterFace = nearFace;
        }
        if (tFar < span.tExit) {
            span.tExit = tFar;
            span.exitFace = farFace;
        }
    }
    if (span.tEnter > span.tExit) return std::nullopt;
    return span;
}

std::optional<SurfaceCrossing> Box::cross(const Ray& ray, float tMax) const {
    const std::optional<LineSpan> span = lineSpan(ray);
    if (!span) return std::nullopt;
    // From outside the box the entry is the crossing; from inside (or on the surface, leaving)
    // the exit is.
    if (span->tEnter > 0 && span->tEnter < tMax)
        return SurfaceCrossing{span->tEnter, span->tEnter, span->enterFace};
    if (span->tExit > 0 && span->tExit < tMax)
        return SurfaceCrossing{span->tExit, span->tExit, span->exitFace};
    return std::nullopt;
}

void Box::crossLine(const Ray& ray, LineCrossings& crossings) const {
    const std::optional<LineSpan> span = lineSpan(ray);
    // A line along a face (d = 0 on its axis, o on its plane) runs on the surface: no crossing.
    if (!span || !std::isfinite(span->tEnter)) return;
    crossings.push_back({SurfaceCrossing{span->tEnter, span->tEnter, span->enterFace}, true});
    crossings.push_back({SurfaceCrossing{span->tExit, span->tExit, span->exitFace}, false});
}

Hit Box::record(const Ray& ray, const SurfaceCrossing& crossing) const {
    const Face f = face(crossing.primitive);
    // The point put exactly on the face's plane and inside its rectangle: the rounding of t
    // moves it only along the face.
    const Vec3d found = Vec3d(ray.origin) + crossing.tShape * Vec3d(ray.direction);
    Vec3 p;
    p[f.axis] = f.position;
    for (const int axis : {f.uAxis, f.vAxis})
        p[axis] = std::clamp(static_cast<float>(found[axis]), min_[axis], max_[axis]);
    Hit hit = Hit::atRoundedPoint(crossing.tShape, p, f.normal);
    hit.pError[f.axis] = 0;
    const float uExtent = max_[f.uAxis] - min_[f.uAxis], vExtent = max_[f.vAxis] - min_[f.vAxis];
    hit.setUv({(p[f.uAxis] - min_[f.uAxis]) / uExtent, (p[f.vAxis] - min_[f.vAxis]) / vExtent});
    hit.dpdu = Vec3(0);
    hit.dpdu[f.uAxis] = uExtent;
    hit.dpdv = Vec3(0);
    hit.dpdv[f.vAxis] = vExtent;
    hit.shape = this;
    hit.primitive = crossing.primitive;
    hit.material = material();
    return hit;
}

float Box::area(std::uint32_t index) const {
    const Face f = face(index);
    return (max_[f.uAxis] - min_[f.uAxis]) * (max_[f.vAxis] - min_[f.vAxis]);
}

std::optional<ShapeSample> Box::sample(std::uint32_t index, const Vec2& u) const {
    const Face f = face(index);
    return ShapeSample{pointAt(f, u.x, u.y), f.normal, 1 / area(index)};
}

Tessellation Box::tessellate(const TessellationRequest& request) const {
    const auto piecesFor = [&](float length) {
        return std::clamp(static_cast<int>(std::ceil(length / request.patchSize)), 1, 4096);
    };
    Tessellation tessellation;
    for (std::uint32_t index = 0; index < 6; ++index) {
        const Face f = face(index);
        const int columns = piecesFor(max_[f.uAxis] - min_[f.uAxis]);
        const int rows = piecesFor(max_[f.vAxis] - min_[f.vAxis]);
        const auto at = [&](int i, int j) {
            return pointAt(f, static_cast<float>(i) / static_cast<float>(columns),
                           static_cast<float>(j) / static_cast<float>(rows));
        };
        // Counter-clockwise seen from outside, since dpdu x dpdv points out.
        for (int j = 0; j < rows; ++j)
            for (int i = 0; i < columns; ++i) {
                tessellation.facets.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}, index});
                tessellation.facets.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}, index});
            }
    }
    return tessellation;
}

}  // namespace lancer
