#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/Cone.h"

namespace lancer {

// A circular cylinder of radius r from `base` to `top`: the cone of equal radii.
class Cylinder final : public Cone {
public:
    Cylinder(const Vec3& base, const Vec3& top, float radius, bool open, const Material* material)
        : Cone(base, radius, top, radius, open, material) {}
    // The scene file's "cylinder": base, top (distinct), radius (> 0), open (default false).
    static std::vector<std::string> keys() { return {"base", "top", "radius", "open"}; }
    static std::unique_ptr<Shape> create(const Parameters& parameters, const Material* material);
};

}  // namespace lancer
