#pragma once

#include "materials/Texture.h"

namespace lancer {

// Squares of side `scale` in uv space: `even` where floor(u/scale) + floor(v/scale) is even.
class CheckerTexture final : public Texture {
public:
    CheckerTexture(const Color& even, const Color& odd, float scale);
    Color evaluate(const Hit& hit) const override;

private:
    Color even_, odd_;
    float scale_;
};

}  // namespace lancer
