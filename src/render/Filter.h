#pragma once

#include <memory>
#include <string>
#include <vector>

#include "math/Vec2.h"

namespace lancer {

struct FilterSettings;

// A pixel reconstruction filter: the weight of a sample at offset (x, y) pixels from the pixel
// centre. Every filter here is separable, f(x, y) = profile(x) profile(y), zero beyond radius()
// along each axis, and normalised: the profile integrates to 1 over [-radius, radius], so f
// integrates to 1 over the plane.
class Filter {
public:
    virtual ~Filter() = default;

    float radius() const { return radius_; }
    virtual float profile(float x) const = 0;
    float evaluate(const Vec2& offset) const { return profile(offset.x) * profile(offset.y); }

    // The filter `settings` names, with its type's default radius when it gives none. Throws
    // std::invalid_argument for a type not in typeNames() or a radius that is not > 0.
    static std::unique_ptr<Filter> create(const FilterSettings& settings);
    // "box", "tent", "gaussian", "mitchell".
    static const std::vector<std::string>& typeNames();

protected:
    explicit Filter(float radius) : radius_(radius) {}

private:
    float radius_;
};

}  // namespace lancer
