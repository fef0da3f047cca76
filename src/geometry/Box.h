#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/Shape.h"
#include "util/Parameters.h"

namespace lancer {

// An axis-aligned box between the corners min and max: a closed solid whose normals point out.
// Its six faces are its primitives, numbered 2 axis + side (side 1 for the face at max[axis]),
// so that each can carry its own light samples and patches. On each face uv runs from 0 to 1
// across the face's two other axes, oriented so that dpdu x dpdv points out of the box: on a
// max face u follows axis + 1 and v axis + 2 (mod 3), on a min face the other way round.
class Box final : public Shape {
public:
    Box(const Vec3& min, const Vec3& max, const Material* material);
    // The scene file's "box": min and max, min < max on every axis.
    static std::vector<std::string> keys() { return {"min", "max"}; }
    static std::unique_ptr<Shape> create(const Parameters& parameters, const Material* material);

    std::optional<SurfaceCrossing> cross(const Ray& ray, float tMax) const override;
    Hit record(const Ray& ray, const SurfaceCrossing& crossing) const override;
    Bounds3 bounds() const override { return {min_, max_}; }
    bool isSolid() const override { return true; }
    void crossLine(const Ray& ray, LineCrossings& crossings) const override;
    // A solid's surface gives light to its outside only.
    bool emitsOnBothSides() const override { return false; }
    std::uint32_t primitiveCount() const override { return 6; }
    float area(std::uint32_t face) const override;
    std::optional<ShapeSample> sample(std::uint32_t face, const Vec2& u) const override;
    // Each face cut into a grid of rectangles about the patch size, two triangles each.
    Tessellation tessellate(const TessellationRequest& request) const override;

private:
    // Where the ray's line enters the box and leaves it, and through which faces.
    struct LineSpan {
        double tEnter, tExit;
        std::uint32_t enterFace, exitFace;
    };
    std::optional<LineSpan> lineSpan(const Ray& ray) const;
    // How a face lies: the axis it is normal to, the corner coordinate it sits at, and the axes
    // its u and v follow.
    struct Face {
        int axis, uAxis, vAxis;
        float position;
        Vec3 normal;
    };
    Face face(std::uint32_t index) const;
    // The point of a face at (u, v) in [0, 1]^2.
    Vec3 pointAt(const Face& f, float u, float v) const;

    Vec3 min_, max_;
};

}  // namespace lancer
