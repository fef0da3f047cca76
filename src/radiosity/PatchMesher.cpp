#include "radiosity/PatchMesher.h"

#include <algorithm>
#include <cmath>

#include "geometry/Shape.h"
#include "materials/Material.h"
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
    const Tessellation tessellation = shape.tessellate({patchSize_, clipBox_});
    for (const Tessellation::Facet& facet : tessellation.facets) {
        const Material* material = shape.primitiveMaterial(facet.primitive);
        if (!material || !isMeshed(*material)) continue;
        addSurfaceTriangle(mesh, facet.corners,
                           {&shape, material, shape.emitsOnBothSides(), tessellation.curved,
                            tessellation.probeDistance});
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
        const Color emission = material.hasTexturedEmission() ? SurfaceProbe::emission(patch, piece)
                                                              : material.emission();
        patch.emission[0] = emission;
        patch.emission[1] = source.emitsOnBothSides ? emission : Color(0);
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
