#pragma once

#include <memory>
#include <string>
#include <vector>

#include "math/Vec2.h"
#include "util/Registry.h"

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

    // A filter the scene's "filter" can name, with its default radius.
    struct Type {
        const char* name;
        float defaultRadius;
        std::unique_ptr<Filter> (*create)(float radius);
    };
    // The filters, by name: one registration line each.
    static const Registry<Type>& types();

    // The filter `settings` names, with its type's default radius when it gives none. Throws
    // std::invalid_argument for a type not in types() or a radius that is not > 0.
    static std::unique_ptr<Filter> create(const FilterSettings& settings);

protected:
    explicit Filter(float radius) : radius_(radius) {}

private:
    float radius_;
};

}  // namespace lancer
