#include "geometry/Hit.h"

#include "geometry/Shape.h"

namespace lancer {

Vec2 Hit::uv() const {
    return uvShape_ ? uvShape_->uvAt(uvLocal_) : uv_;
}

}  // namespace lancer
