#include "radiosity/PatchMesher.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <utility>

#include "geometry/ConvexPolygon.h"
#include "geometry/Hit.h"
#include "geometry/Shape.h"
#include "geometry/Tessellation.h"
#include "materials/Material.h"
#include "math/Ray.h"
#include "radiosity/ContactCutter.h"
#include "radiosity/SurfaceProbe.h"
#include "scene/Scene.h"

namespace lancer {

namespace {

// Whether a material takes part in radiosity: it reflects diffusely or it emits.
bool isMeshed(const Material& m) {
    return m.reflectsDiffusely() || !m.emission().isBlack();
}

int piecesFor(float length, float size) {
    return std::clamp(static_cast<int>(std::ceil(length / size)), 1, 4096);
}

// Every facet, with the size of its shape (an infinite plane's: its clip box's).
std::vector<ContactCutter::Facet> allFacets(const std::vector<const Shape*>& shapes,
                                            const std::vector<Tessellation>& tessellations,
                                            const Bounds3& clipBox) {
    std::vector<ContactCutter::Facet> facets;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const float reach =
            length((shapes[i]->isBounded() ? shapes[i]->bounds() : clipBox).diagonal());
        for (const Tessellation::Facet& facet : tessellations[i].facets)
            facets.push_back({facet.corners, reach});
    }
    return facets;
}

}  // namespace

PatchMesher::PatchMesher(const Scene& scene, const RadiositySettings& settings) : scene_(scene) {
    Bounds3 shapes;
    for (const auto& shape : scene.boundedShapes())
        shapes = merge(shapes, shape->bounds());
    clipBox_ = merge(shapes, scene.camera().position());
    // Planes reach a little beyond everything else, so that the box's edges are not seen.
    const float margin = std::max(0.05f * length(clipBox_.diagonal()), 1e-3f);
    clipBox_ = Bounds3(clipBox_.min - Vec3(margin), clipBox_.max + Vec3(margin));
    const float sceneSize = length((shapes.isEmpty() ? clipBox_ : shapes).diagonal());
    contactTolerance_ = 1e-4f * sceneSize;
    patchSize_ = settings.patchSize > 0 ? settings.patchSize : sceneSize / 8;
    elementSize_ =
        settings.elementSize > 0 ? std::min(settings.elementSize, patchSize_) : patchSize_ / 2;
}

RadiosityMesh PatchMesher::mesh() const {
    // Every shape's facets first: where they meet the other surfaces, those are cut.
    std::vector<const Shape*> shapes;
    for (const auto& shape : scene_.boundedShapes())
        shapes.push_back(shape.get());
    for (const auto& shape : scene_.unboundedShapes())
        shapes.push_back(shape.get());
    std::vector<Tessellation> tessellations;
    tessellations.reserve(shapes.size());
    for (const Shape* shape : shapes)
        tessellations.push_back(shape->tessellate({patchSize_, clipBox_}));
    const ContactCutter cutter(allFacets(shapes, tessellations, clipBox_), contactTolerance_);
    const std::vector<std::vector<bool>> repeated = repeatedFacets(shapes, tessellations);
    RadiosityMesh mesh;
    for (std::size_t i = 0; i < shapes.size(); ++i)
        addShape(mesh, *shapes[i], tessellations[i], repeated[i], cutter);
    return mesh;
}

std::vector<std::vector<bool>> PatchMesher::repeatedFacets(
    const std::vector<const Shape*>& shapes, const std::vector<Tessellation>& tessellations) const {
    // A facet's place: its corners rounded to the contact tolerance, in a fixed order.
    using Corner = std::array<std::int64_t, 3>;
    using Place = std::array<Corner, 3>;
    struct First {
        Vec3 normal;
        std::array<bool, 2> emits;  // along its normal, against it
    };
    std::map<Place, First> firsts;
    std::vector<std::vector<bool>> repeated(shapes.size());
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const Shape& shape = *shapes[i];
        repeated[i].assign(tessellations[i].facets.size(), false);
        for (std::size_t f = 0; f < tessellations[i].facets.size(); ++f) {
            const Tessellation::Facet& facet = tessellations[i].facets[f];
            const Material* material = shape.primitiveMaterial(facet.primitive);
            if (!material || !isMeshed(*material)) continue;
            Place place;
            for (std::size_t k = 0; k < 3; ++k)
                for (int axis = 0; axis < 3; ++axis)
                    place[k][static_cast<std::size_t>(axis)] =
                        std::llround(facet.corners[k][axis] / contactTolerance_);
            std::sort(place.begin(), place.end());
            const std::array<Vec3, 3>& c = facet.corners;
            const Vec3 normal = cross(c[1] - c[0], c[2] - c[0]);
            const bool emits = !material->emission().isBlack();
            const First facetSides{normal, {emits, emits && shape.emitsOnBothSides()}};
            const auto [at, inserted] = firsts.try_emplace(place, facetSides);
            if (inserted) continue;
            // Its emitting sides, seen from the first's normal.
            const bool reversed = dot(normal, at->second.normal) < 0;
            const bool emitsAlong = facetSides.emits[reversed ? 1 : 0];
            const bool emitsAgainst = facetSides.emits[reversed ? 0 : 1];
            repeated[i][f] =
                (!emitsAlong || at->second.emits[0]) && (!emitsAgainst || at->second.emits[1]);
        }
    }
    return repeated;
}

void PatchMesher::addShape(RadiosityMesh& mesh, const Shape& shape,
                           const Tessellation& tessellation, const std::vector<bool>& repeated,
                           const ContactCutter& cutter) const {
    for (std::size_t f = 0; f < tessellation.facets.size(); ++f) {
        if (repeated[f]) continue;
        const Tessellation::Facet& facet = tessellation.facets[f];
        const Material* material = shape.primitiveMaterial(facet.primitive);
        if (!material || !isMeshed(*material)) continue;
        const Source source{&shape, material, shape.emitsOnBothSides(), tessellation.curved,
                            tessellation.probeDistance};
        const std::array<Vec3, 3>& c = facet.corners;
        const Vec3 normal = normalize(cross(c[1] - c[0], c[2] - c[0]));
        const std::array<Vec3d, 3> triangle{Vec3d(c[0]), Vec3d(c[1]), Vec3d(c[2])};
        // Chords of a curved surface are not where anything stands: they are not cut.
        std::optional<float> reach;
        if (!tessellation.curved && isFinite(normal))
            reach = cutter.cuttingReach(triangle, Vec3d(normal));
        if (!reach) {
            addSurfaceTriangle(mesh, facet.corners, source);
            continue;
        }
        // Cut into the cells of a grid first, then along the contact lines: a line then splits
        // only the cells it crosses, not the whole surface (long slivers, whose elements would
        // spread each value far beyond the element size, and many more patches).
        for (const std::vector<Vec3d>& cell :
             gridCells({triangle.begin(), triangle.end()}, normal)) {
            ContactCutter::Pieces parts = cutter.cut(cell, Vec3d(normal));
            if (parts.polygons.empty()) parts.polygons = {cell};
            for (const std::vector<Vec3d>& part : parts.polygons) {
                if (isEnclosed(part, normal, *reach)) continue;
                // A fan: the part is convex. Its triangles thinner than the tolerance are
                // rounding (a cell cut through its corner), not surface.
                for (std::size_t k = 1; k + 1 < part.size(); ++k) {
                    const Vec3d a = part[k] - part[0], b = part[k + 1] - part[0];
                    const double longest =
                        std::max({length(a), length(b), length(part[k + 1] - part[k])});
                    if (length(cross(a, b)) <= contactTolerance_ * longest) continue;
                    addSurfaceTriangle(mesh, {Vec3(part[0]), Vec3(part[k]), Vec3(part[k + 1])},
                                       source);
                }
            }
        }
    }
}

std::vector<std::vector<Vec3d>> PatchMesher::gridCells(const std::vector<Vec3d>& polygon,
                                                       const Vec3& normal) const {
    // Axes fixed by the plane alone, so that neighbouring triangles share a grid.
    Vec3 su, sv;
    coordinateSystem(normal, su, sv);
    const Vec3d u(su), v(sv);
    // Square cells whose halves' longest edge is the patch size: one patch each.
    const double size = patchSize_ * std::sqrt(0.5);
    const auto range = [&](const std::vector<Vec3d>& part, const Vec3d& axis) {
        double lo = dot(axis, part[0]), hi = lo;
        for (const Vec3d& p : part) {
            lo = std::min(lo, dot(axis, p));
            hi = std::max(hi, dot(axis, p));
        }
        return std::pair{std::floor(lo / size), hi};
    };
    std::vector<std::vector<Vec3d>> cells;
    const auto [uFirst, uEnd] = range(polygon, u);
    for (double i = uFirst; i * size < uEnd; ++i) {
        const std::vector<Vec3d> strip =
            clipPolygon(clipPolygon(polygon, u, i * size), -u, -(i + 1) * size);
        if (strip.empty()) continue;
        const auto [vFirst, vEnd] = range(strip, v);
        for (double j = vFirst; j * size < vEnd; ++j) {
            std::vector<Vec3d> cell =
                clipPolygon(clipPolygon(strip, v, j * size), -v, -(j + 1) * size);
            if (!cell.empty()) cells.push_back(std::move(cell));
        }
    }
    return cells;
}

bool PatchMesher::isEnclosed(const std::vector<Vec3d>& piece, const Vec3& normal,
                             float reach) const {
    Vec3d centre(0);
    for (const Vec3d& p : piece)
        centre += p;
    // Above a solid's base, which lies within the tolerance of the surface.
    const Vec3 origin =
        Vec3(centre / static_cast<double>(piece.size())) + 2 * contactTolerance_ * normal;
    // Along the normal and four directions 45 degrees from it: an object only leaning over the
    // piece (a slanted panel, a table) lets some of them out.
    Vec3 s, t;
    coordinateSystem(normal, s, t);
    const float tilt = std::sqrt(0.5f);
    const std::array<Vec3, 5> directions{normal, tilt * (normal + s), tilt * (normal - s),
                                         tilt * (normal + t), tilt * (normal - t)};
    return std::all_of(directions.begin(), directions.end(), [&](const Vec3& direction) {
        const Ray ray{origin, direction};
        // Twice the cutting shape's size: a solid given as separate faces is larger than each.
        const std::optional<Hit> hit = scene_.intersect(ray, 2 * reach);
        return hit && !hit->frontFace(ray) && !(hit->material && hit->material->isTransmissive());
    });
}

void PatchMesher::addSurfaceTriangle(RadiosityMesh& mesh, const std::array<Vec3, 3>& corners,
                                     const Source& source) const {
    const Vec3 crossed = cross(corners[1] - corners[0], corners[2] - corners[0]);
    if (!(lengthSquared(crossed) > 0) || !isFinite(crossed)) return;
    const Material& material = *source.material;
    for (const auto& piece : RadiosityMesh::subdivide(
             corners, piecesFor(RadiosityMesh::longestEdge(corners), patchSize_))) {
        Patch patch;
        patch.corners = piece;
        const Vec3 n = cross(piece[1] - piece[0], piece[2] - piece[0]);
        patch.area = 0.5f * length(n);
        if (!(patch.area > 0)) continue;
        patch.normal = normalize(n);
        patch.surface = source.surface;
        patch.material = source.material;
        patch.curved = source.curved;
        patch.probeDistance = source.curved ? source.probeDistance : 1e-3f * std::sqrt(patch.area);
        const Color emission = material.hasTexturedEmission() ? SurfaceProbe::emission(patch, piece)
                                                              : material.emission();
        patch.emission[0] = emission;
        patch.emission[1] = source.emitsOnBothSides ? emission : Color(0);
        // An area light's own surface: its light shoots from the light source instead.
        if (source.surface->areaLight()) patch.emission = {};
        const auto index = static_cast<std::uint32_t>(mesh.patches.size());
        patch.firstElement = static_cast<std::uint32_t>(mesh.elements.size());
        mesh.patches.push_back(patch);
        for (const auto& part : RadiosityMesh::subdivide(
                 piece, piecesFor(RadiosityMesh::longestEdge(piece), elementSize_))) {
            const std::uint32_t e = mesh.addElement(index, part, 0);
            SurfaceProbe::place(mesh.patches[index], part, mesh.elements[e]);
        }
        mesh.patches[index].elementCount =
            static_cast<std::uint32_t>(mesh.elements.size()) - mesh.patches[index].firstElement;
    }
}

}  // namespace lancer
