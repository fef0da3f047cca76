#include "geometry/Hit.h"

#include "geometry/Shape.h"

namespace lancer {

bool Hit::seesEmittingSide(const Ray& ray) const {
    return frontFace(ray) || shape->emitsOnBothSides();
}

Vec2 Hit::uv() const {
    return uvShape_ ? uvShape_->uvAt(uvLocal_) : uv_;
}

}  // namespace lancer
