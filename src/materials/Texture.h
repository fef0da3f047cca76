#pragma once

#include "geometry/Hit.h"
#include "math/Color.h"

namespace lancer {

// A colour that varies over a surface, looked up at a hit's uv.
class Texture {
public:
    virtual ~Texture() = default;
    virtual Color evaluate(const Hit& hit) const = 0;
    // Its mean over the uv square: the uniform value that stands in for it (a textured light's
    // power, by which lights are picked).
    virtual Color average() const = 0;
    // Whether it is black everywhere, as far as the texture can tell without looking.
    virtual bool isBlack() const { return false; }
    // Whether evaluate reads the hit's uv footprint (dudx...), which is then worth computing.
    virtual bool readsFootprint() const { return false; }
};

}  // namespace lancer
