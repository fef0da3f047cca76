#include "geometry/Cylinder.h"

namespace lancer {

std::unique_ptr<Shape> Cylinder::create(const Parameters& parameters, const Material* material) {
    const Vec3 base = parameters.point("base"), top = parameters.point("top");
    checkAxis(parameters, base, top);
    const bool open = parameters.has("open") && parameters.flag("open");
    return std::make_unique<Cylinder>(base, top, parameters.numberAbove("radius", 0, false), open,
                                      material);
}

}  // namespace lancer
