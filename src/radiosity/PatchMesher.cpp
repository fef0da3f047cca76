#include "radiosity/PatchMesher.h"

#include <algorithm>
#include <cmath>

#include "accel/Mesh.h"
#include "geometry/Instance.h"
#include "geometry/Plane.h"
#include "geometry/Quad.h"
#include "geometry/Sphere.h"
#include "geometry/Triangle.h"
#include "materials/Material.h"
#include "radiosity/ConvexPolygon.h"
#include "radiosity/SurfaceProbe.h"
#include "scene/Scene.h"

namespace lancer {

namespace {

// Whether a material takes part in radiosity: it reflects diffusely or it emits.
bool isMeshed(const Material& m) {
    return m.reflectsDiffusely() || !m.emission().isBlack();
}

float longestEdge(const std::array<Vec3, 3>& t) {
    return std::max({length(t[1] - t[0]), length(t[2] - t[1]), length(t[0] - t[2])});
}

int piecesFor(float length, float size) {
    return std::clamp(static_cast<int>(std::ceil(length / size)), 1, 4096);
}

bool flipsOrientation(const Transform& t) {
    const auto& m = t.matrix();
    const float det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                      m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                      m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return det < 0;
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
    patchSize_ = settings.patchSize > 0 ? settings.patchSize : sceneSize / 8;
    elementSize_ =
        settings.elementSize > 0 ? std::min(settings.elementSize, patchSize_) : patchSize_ / 2;
}

RadiosityMesh PatchMesher::mesh() const {
    RadiosityMesh mesh;
    for (const auto& shape : scene_.boundedShapes())
        addShape(mesh, *shape);
    for (const auto& shape : scene_.unboundedShapes())
        addShape(mesh, *shape);
    return mesh;
}

void PatchMesher::addShape(RadiosityMesh& mesh, const Shape& shape) const {
    // An instance's shape, in the instance's world placement.
    const Shape* placed = &shape;
    Transform toWorld;
    if (const auto* instance = dynamic_cast<const Instance*>(&shape)) {
        placed = &instance->placedShape();
        toWorld = instance->objectToWorld();
    }
    const bool flip = flipsOrientation(toWorld);
    const auto world = [&](std::array<Vec3, 3> t) {
        for (Vec3& p : t)
            p = toWorld.applyPoint(p);
        if (flip) std::swap(t[1], t[2]);  // keep the front on the side the shape's normal is
        return t;
    };
    const auto sourceFor = [&](const Material* material) -> std::optional<Source> {
        if (shape.material()) material = shape.material();  // an instance's override
        if (!material || !isMeshed(*material)) return std::nullopt;
        return Source{&shape, material, shape.emitsOnBothSides(), false, 0};
    };

    if (const auto* triangle = dynamic_cast<const Triangle*>(placed)) {
        if (const auto source = sourceFor(triangle->material()))
            addSurfaceTriangle(mesh, world(triangle->vertices()), *source);
    } else if (const auto* model = dynamic_cast<const Mesh*>(placed)) {
        const TriangleMesh& m = model->triangles();
        for (std::size_t i = 0; i < m.triangleCount(); ++i) {
            const Material* material =
                m.materials.empty() ? placed->material() : m.materials[m.faceMaterials[i]].get();
            const auto source = sourceFor(material);
            if (!source) continue;
            const std::uint32_t* v = &m.indices[3 * i];
            addSurfaceTriangle(
                mesh, world({m.positions[v[0]], m.positions[v[1]], m.positions[v[2]]}), *source);
        }
    } else if (const auto* quad = dynamic_cast<const Quad*>(placed)) {
        if (const auto source = sourceFor(quad->material())) {
            const Vec3 a = quad->corner(), b = a + quad->edge1(), c = b + quad->edge2(),
                       d = a + quad->edge2();
            addSurfaceTriangle(mesh, world({a, b, c}), *source);
            addSurfaceTriangle(mesh, world({a, c, d}), *source);
        }
    } else if (const auto* sphere = dynamic_cast<const Sphere*>(placed)) {
        if (const auto source = sourceFor(sphere->material()))
            addSphere(mesh, *source, sphere->center(), sphere->radius(), toWorld);
    } else if (const auto* plane = dynamic_cast<const Plane*>(placed)) {
        const auto source = sourceFor(plane->material());
        if (!source) return;
        const Vec3 point = toWorld.applyPoint(plane->point());
        const Vec3 normal = normalize(toWorld.applyNormal(plane->normal()));
        // A square around the box's centre, large enough to cover the box, clipped to it.
        Vec3 a, b;
        coordinateSystem(normal, a, b);
        const Vec3 centre = clipBox_.centroid();
        const Vec3 onPlane = centre - dot(centre - point, normal) * normal;
        const float half = length(clipBox_.diagonal());
        std::vector<Vec3d> polygon;
        for (const auto& [s, t] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
            polygon.emplace_back(onPlane +
                                 half * (static_cast<float>(s) * a + static_cast<float>(t) * b));
        for (int axis = 0; axis < 3 && !polygon.empty(); ++axis) {
            Vec3d n;
            n[axis] = 1;
            polygon = clipPolygon(polygon, n, clipBox_.min[axis]);
            if (!polygon.empty()) polygon = clipPolygon(polygon, -n, -clipBox_.max[axis]);
        }
        for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
            std::array<Vec3, 3> t{Vec3(polygon[0]), Vec3(polygon[i]), Vec3(polygon[i + 1])};
            // The plane's normal is its front.
            if (dot(cross(t[1] - t[0], t[2] - t[0]), normal) < 0) std::swap(t[1], t[2]);
            addSurfaceTriangle(mesh, t, *source);
        }
    }
}

void PatchMesher::addSphere(RadiosityMesh& mesh, Source source, const Vec3& center, float radius,
                            const Transform& objectToWorld) const {
    // A latitude-longitude grid, with as many rows and columns as the world-space size asks.
    float stretch = 0;
    for (int axis = 0; axis < 3; ++axis) {
        Vec3 unit;
        unit[axis] = 1;
        stretch = std::max(stretch, length(objectToWorld.applyVector(unit)));
    }
    const float worldRadius = radius * stretch;
    const int columns = std::max(8, piecesFor(2 * kPi * worldRadius, patchSize_));
    const int rows = std::max(4, piecesFor(kPi * worldRadius, patchSize_));
    const auto at = [&](int row, int column) {
        const float theta = kPi * static_cast<float>(row) / static_cast<float>(rows);
        const float phi =
            2 * kPi * static_cast<float>(column % columns) / static_cast<float>(columns);
        return center + radius * Vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                      -std::sin(theta) * std::sin(phi));
    };
    // The deepest a chord sinks below the surface is about r (1 - cos(a / 2)) for the cell's
    // angular width a; the probe starts beyond twice the widest cell's, with a margin.
    const float widest = 2 * kPi / static_cast<float>(std::min(columns, 2 * rows));
    source.curved = true;
    source.probeDistance = 2 * worldRadius * (1 - std::cos(widest)) + 1e-4f * worldRadius;
    const bool flip = flipsOrientation(objectToWorld);
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            const Vec3 p00 = at(row, column), p01 = at(row, column + 1), p10 = at(row + 1, column),
                       p11 = at(row + 1, column + 1);
            std::vector<std::array<Vec3, 3>> cells;
            // Counter-clockwise seen from outside: the outside is the sphere's front.
            if (row > 0) cells.push_back({p00, p10, p01});
            if (row < rows - 1) cells.push_back({p01, p10, p11});
            for (auto& t : cells) {
                for (Vec3& p : t)
                    p = objectToWorld.applyPoint(p);
                if (flip) std::swap(t[1], t[2]);
                addSurfaceTriangle(mesh, t, source);
            }
        }
}

void PatchMesher::addSurfaceTriangle(RadiosityMesh& mesh, const std::array<Vec3, 3>& corners,
                                     const Source& source) const {
    const Vec3 crossed = cross(corners[1] - corners[0], corners[2] - corners[0]);
    if (!(lengthSquared(crossed) > 0) || !isFinite(crossed)) return;
    const Material& material = *source.material;
    for (const auto& piece :
         RadiosityMesh::subdivide(corners, piecesFor(longestEdge(corners), patchSize_))) {
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
        patch.emission[0] = material.emission();
        patch.emission[1] = source.emitsOnBothSides ? material.emission() : Color(0);
        // An area light's own surface: its light shoots from the light source instead.
        if (source.surface->areaLight()) patch.emission = {};
        const auto index = static_cast<std::uint32_t>(mesh.patches.size());
        patch.firstElement = static_cast<std::uint32_t>(mesh.elements.size());
        mesh.patches.push_back(patch);
        for (const auto& part :
             RadiosityMesh::subdivide(piece, piecesFor(longestEdge(piece), elementSize_))) {
            const std::uint32_t e = mesh.addElement(index, part, 0);
            SurfaceProbe::place(mesh.patches[index], part, mesh.elements[e]);
        }
        mesh.patches[index].elementCount =
            static_cast<std::uint32_t>(mesh.elements.size()) - mesh.patches[index].firstElement;
    }
}

}  // namespace lancer
