#include "geometry/Shape.h"

#include "materials/Material.h"

namespace lancer {

bool Shape::hasTransmissiveMaterial() const {
    return material_ && material_->isTransmissive();
}

}  // namespace lancer
