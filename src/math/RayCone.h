#pragma once

namespace lancer {

// A sample's share of a pixel carried along a ray, for texture filtering (ray cones): `width`
// across at the ray's origin, growing by `spread` (an angle, in radians) per unit of distance.
// A pinhole's cone starts at a point; an orthographic camera's keeps its width.
struct RayCone {
    float width = 0;
    float spread = 0;

    float widthAt(float distance) const { return width + distance * spread; }
    RayCone scaled(float factor) const { return {width * factor, spread * factor}; }
};

}  // namespace lancer
