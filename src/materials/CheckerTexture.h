#pragma once

#include <memory>
#include <string>
#include <vector>

#include "materials/Texture.h"
#include "util/Parameters.h"

namespace lancer {

// Squares of side `scale` in uv space: `even` where floor(u/scale) + floor(v/scale) is even.
class CheckerTexture final : public Texture {
public:
    CheckerTexture(const Color& even, const Color& odd, float scale);
    // The scene file's {"checker": {"even": A, "odd": B, "scale": s}}, every key optional
    // (white, black, 1).
    static std::vector<std::string> keys() { return {"even", "odd", "scale"}; }
    static std::shared_ptr<const Texture> create(const Parameters& parameters);
    Color evaluate(const Hit& hit) const override;
    Color average() const override { return 0.5f * (even_ + odd_); }

private:
    Color even_, odd_;
    float scale_;
};

}  // namespace lancer
