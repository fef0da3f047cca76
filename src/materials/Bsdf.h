#pragma once

#include <array>
#include <cstddef>
#include <new>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "materials/BsdfLobe.h"
#include "materials/BsdfSample.h"
#include "math/Frame.h"

namespace lancer {

class Material;
struct Hit;

// How a material scatters light at one hit point: the lobes its material adds (at most
// kMaxLobes), held inline, since the path tracer builds one at every bounce. For the path tracer,
// energy is conserved: when the lobes' weights sum to more than 1 in some channel, all weights
// are divided by the largest channel sum, so that no light is created. One lobe is sampled,
// chosen in proportion to its (scaled) weight averaged over the channels.
//
// Directions are in world space, unit length and point away from the surface. The lobes live in
// the frame of the shading normal (turned to the front side); light that would cross the
// geometric surface the wrong way (a reflection lobe reaching below the true surface because of
// a smooth-shading normal) is cut.
class Bsdf {
public:
    static constexpr std::size_t kMaxLobes = 4;

    Bsdf(const Material& material, const Hit& hit);
    // The lobes point into the object's own storage.
    Bsdf(const Bsdf&) = delete;
    Bsdf& operator=(const Bsdf&) = delete;

    // Adds a lobe made from args; one of black weight adds nothing.
    template <class Lobe, class... Args>
    void add(Args&&... args);

    // The sum of the non-delta lobes (delta lobes give 0).
    Color f(const Vec3& wo, const Vec3& wi) const;
    // The density with which sample() returns wi through a non-delta lobe.
    float pdf(const Vec3& wo, const Vec3& wi) const;
    // A direction from one lobe chosen by uLobe, sampled with u. For a non-delta lobe, f and pdf
    // are those of the whole BSDF (the one-sample mixture); for a delta lobe, its own weight
    // and its selection probability.
    std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const;

    // Whether some lobe can be evaluated for a given pair of directions (light sampling is then
    // worthwhile).
    bool hasNonDeltaLobe() const;
    // The shading normal on the front side.
    const Vec3& shadingNormal() const { return frame_.n; }

private:
    // Room for the largest lobe, a vtable pointer and a few colours.
    static constexpr std::size_t kLobeSize = 48;
    struct alignas(alignof(std::max_align_t)) LobeStorage {
        std::byte bytes[kLobeSize];
    };

    // Divides the weights for energy conservation and sets the lobes' probabilities.
    void weighLobes();

    // Whether wo and wi lie on the sides of the geometric surface that a reflection needs.
    bool reflectsGeometrically(const Vec3& wo, const Vec3& wi) const {
        return dot(wo, ng_) * dot(wi, ng_) > 0;
    }

    Frame frame_;
    Vec3 ng_;
    std::size_t lobeCount_ = 0;
    std::array<LobeStorage, kMaxLobes> storage_;
    std::array<BsdfLobe*, kMaxLobes> lobes_{};
    std::array<float, kMaxLobes> probabilities_{};  // of choosing each lobe
};

template <class Lobe, class... Args>
void Bsdf::add(Args&&... args) {
    static_assert(std::is_base_of_v<BsdfLobe, Lobe>);
    static_assert(sizeof(Lobe) <= kLobeSize && alignof(Lobe) <= alignof(LobeStorage),
                  "the lobe does not fit the Bsdf's storage: raise kLobeSize");
    static_assert(std::is_trivially_destructible_v<Lobe>, "the Bsdf never destroys its lobes");
    if (lobeCount_ == kMaxLobes) throw std::length_error("more lobes than Bsdf::kMaxLobes");
    Lobe* lobe = ::new (storage_[lobeCount_].bytes) Lobe(std::forward<Args>(args)...);
    if (!lobe->weight().isBlack()) lobes_[lobeCount_++] = lobe;
}

}  // namespace lancer
