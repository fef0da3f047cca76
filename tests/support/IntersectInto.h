#pragma once

#include "geometry/Hit.h"
#include "math/Ray.h"

namespace lancer::test {

// The nearest hit of a shape or scene into `hit` (left untouched on a miss): the tests' way of
// keeping one record across several queries.
template <typename Intersectable>
bool intersectInto(const Intersectable& target, const Ray& ray, float tMax, Hit& hit) {
    const auto found = target.intersect(ray, tMax);
    if (found) hit = *found;
    return found.has_value();
}

}  // namespace lancer::test
