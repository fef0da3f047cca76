#pragma once

#include "geometry/TriangleIntersection.h"
#include "geometry/TrianglePack.h"

namespace lancer {

// The hits of a ray on the lanes of a TrianglePack.
struct PackHits {
    int lanes;  // bit i set when lane i is hit
    float t[TrianglePack::kLanes];
    float b0[TrianglePack::kLanes], b1[TrianglePack::kLanes], b2[TrianglePack::kLanes];

    // The hit with the smallest t (the first lane of those at that t). Requires lanes != 0.
    int nearestLane() const {
        int nearest = -1;
        for (int lane = 0; lane < TrianglePack::kLanes; ++lane)
            if ((lanes >> lane & 1) && (nearest < 0 || t[lane] < t[nearest])) nearest = lane;
        return nearest;
    }
    TriangleIntersection at(int lane) const { return {b0[lane], b1[lane], b2[lane], t[lane]}; }
};

}  // namespace lancer
