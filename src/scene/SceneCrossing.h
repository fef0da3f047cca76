#pragma once

#include "geometry/SurfaceCrossing.h"

namespace lancer {

class Shape;

// The nearest crossing of a ray with a scene's shapes, before its record is built.
struct SceneCrossing {
    const Shape* shape;
    SurfaceCrossing crossing;
};

}  // namespace lancer
