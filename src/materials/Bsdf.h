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
#include "materials/SpecularRay.h"
#include "math/Frame.h"

namespace lancer {

class Material;
struct Hit;

// How a material scatters light at one hit point: the lobes its material adds (at most
// kMaxLobes), held inline, since the path tracer builds one at every bounce. For the path tracer
// and radiosity, energy is conserved: when the lobes' weights sum to more than 1 in some channel,
// all weights are divided by the largest channel sum, so that no light is created. One lobe is
// sampled, chosen in proportion to its (scaled) weight averaged over the channels.
//
// Whitted and radiosity shade their own way from the same lobes (Whitted with the weights as
// given, the scene format's equation): the lobes' local responses lit by the lights, the delta
// lobes' light traced along specular rays, and (radiosity) the diffuse lobes' albedo, the glossy
// lobes' f and sampled directions, and the rough lobes' traced rays.
//
// Directions are in world space, unit length and point away from the surface. The lobes live in
// the frame of the shading normal (turned to the front side); light that would cross the
// geometric surface the wrong way (a reflection lobe reaching below the true surface because of
// a smooth-shading normal) is cut.
class Bsdf {
public:
    static constexpr std::size_t kMaxLobes = 4;
    // One reflection (the mirror directions coincide) and a refraction per lobe.
    static constexpr std::size_t kMaxSpecularRays = kMaxLobes + 1;

    enum class Weights {
        EnergyConserving,  // the path tracer's
        AsGiven,           // the scene format's equation (Whitted): not for sample()
    };

    // The frame's normal is the material's shading normal at the hit, seen from wo (the
    // direction towards the viewer), which a normal or bump map perturbs.
    Bsdf(const Material& material, const Hit& hit, const Vec3& wo,
         Weights weights = Weights::EnergyConserving);
    // The lobes point into the object's own storage.
    Bsdf(const Bsdf&) = delete;
    Bsdf& operator=(const Bsdf&) = delete;

    // Adds the lobe Lobe(weight, args...) (Material::addLobes does, while the Bsdf is built);
    // one of black weight adds nothing and is not even made.
    template <class Lobe, class... Args>
    void add(const Color& weight, Args&&... args);

    // The sum of the non-delta lobes (delta lobes give 0).
    Color f(const Vec3& wo, const Vec3& wi) const;
    // The density with which sample() returns wi through a non-delta lobe.
    float pdf(const Vec3& wo, const Vec3& wi) const;
    // A direction from one lobe chosen by uLobe, sampled with u. For a non-delta lobe, f and pdf
    // are those of the whole BSDF (the one-sample mixture); for a delta lobe, its own weight
    // and its selection probability.
    std::optional<BsdfSample> sample(const Vec3& wo, float uLobe, const Vec2& u) const;
    // Whether sample() reads uLobe: to choose among lobes, or for the one lobe's own choice.
    bool readsLobeChoice() const;

    // Whether some lobe can be evaluated for a given pair of directions (light sampling is then
    // worthwhile).
    bool hasNonDeltaLobe() const;
    // The shading normal on the front side.
    const Vec3& shadingNormal() const { return frame_.n; }
    // The shading normal on the given side of the geometric surface (front: ng's side).
    Vec3 shadingNormal(bool front) const { return front ? frame_.n : -frame_.n; }

    // Whitted's local model for light arriving from wi, seen from wo on the given side of the
    // surface: the sum of the lobes' local responses, black for light behind that side's
    // shading normal. The rough lobes add f cos(theta_L) for a delta light (point, directional,
    // spot) only: their traced rays find area lights and emitters.
    Color localResponse(const Vec3& wo, const Vec3& wi, bool front, bool deltaLight) const;
    // The rays Whitted traces from wo on the given side: the delta lobes' reflections about the
    // shading normal merged into one, then their refractions. Returns how many were written.
    std::size_t specularRays(const Vec3& wo, bool front,
                             std::array<SpecularRay, kMaxSpecularRays>& rays) const;
    // The rough lobes, each of which Whitted traces with one direction per pixel sample.
    std::size_t roughLobeCount() const { return roughCount_; }
    // The rays the rough lobe `index` traces from wo, drawn with u (BsdfLobe::tracedRays), but
    // those that would cross the geometric surface the wrong way. Returns how many were written.
    std::size_t tracedRays(std::size_t index, const Vec3& wo, const Vec2& u,
                           std::array<SpecularRay, 2>& rays) const;
    // The glossy lobes (neither diffuse, delta nor rough), whose reflection of what is not a light
    // radiosity gathers along one direction per pixel sample.
    std::size_t glossyLobeCount() const { return glossyCount_; }
    // A direction drawn from the glossy lobe `index` with u, as the path tracer samples it, with
    // the weight f cos / pdf of its radiance; none where the lobe gives nothing or the direction
    // would cross the geometric surface the wrong way.
    std::optional<SpecularRay> glossyRay(std::size_t index, const Vec3& wo, const Vec2& u) const;
    // The glossy lobe `index`'s f and density for the pair (no geometric cut, as glossyF): what
    // multiple importance sampling weighs a light's sample against the lobe's own with.
    struct LobeValue {
        Color f;
        float pdf = 0;
    };
    LobeValue glossyLobeValue(std::size_t index, const Vec3& wo, const Vec3& wi) const;
    // The albedo of the ideal diffuse lobes (f = albedo / pi), which radiosity handles.
    const Color& diffuseReflectance() const { return diffuseWeight_; }
    // Whether some lobe is neither diffuse nor delta (highlights).
    bool hasGlossyLobe() const { return glossyCount_ + roughCount_ > 0; }
    // The sum of f over the lobes neither diffuse nor delta, without the geometric cut: the
    // highlights that radiosity adds for the lights, judged by the shading normal alone. The
    // rough lobes count for a delta light only (as in localResponse).
    Color glossyF(const Vec3& wo, const Vec3& wi, bool deltaLight) const;

private:
    // A vtable pointer, the weight and kind, and the rough conductor's roughness and optional
    // complex index (two colours and a flag): 56 bytes.
    static constexpr std::size_t kLobeSize = 64;
    struct alignas(alignof(std::max_align_t)) LobeStorage {
        std::byte bytes[kLobeSize];
    };

    // The sum of the rough lobes' f (no geometric cut), for the highlights of delta lights.
    Color roughF(const Vec3& wo, const Vec3& wi) const;
    // For EnergyConserving weights: divides them if they sum to more than 1 and sets the lobes'
    // probabilities.
    void weighLobes(Weights weights);

    // Whether wo and wi lie on the sides of the geometric surface that a reflection needs.
    bool reflectsGeometrically(const Vec3& wo, const Vec3& wi) const {
        return dot(wo, ng_) * dot(wi, ng_) > 0;
    }
    // Whether a lobe's pair of local directions reflects (or refracts) as the geometric surface
    // does with the same pair in world space: a smooth-shading normal must not let light cross
    // the true surface the wrong way.
    bool sidesAgree(const Vec3& woLocal, const Vec3& wiLocal, bool reflectsGeometrically) const {
        return (woLocal.z * wiLocal.z > 0) == reflectsGeometrically;
    }

    Frame frame_;
    Vec3 ng_;
    std::size_t lobeCount_ = 0;
    std::array<LobeStorage, kMaxLobes> storage_;
    std::array<BsdfLobe*, kMaxLobes> lobes_{};
    // The same lobes by kind, for Whitted's and radiosity's sums, which treat each kind its own
    // way: the diffuse lobes' summed weight (their f and local response follow from it), and
    // the glossy, rough and delta lobes in the order added.
    Color diffuseWeight_;
    std::size_t glossyCount_ = 0, roughCount_ = 0, deltaCount_ = 0;
    std::array<const BsdfLobe*, kMaxLobes> glossyLobes_, roughLobes_, deltaLobes_;
    // Of choosing each lobe, for sample() and pdf(): set for EnergyConserving weights only.
    std::array<float, kMaxLobes> probabilities_{};
};

template <class Lobe, class... Args>
void Bsdf::add(const Color& weight, Args&&... args) {
    static_assert(std::is_base_of_v<BsdfLobe, Lobe>);
    static_assert(sizeof(Lobe) <= kLobeSize && alignof(Lobe) <= alignof(LobeStorage),
                  "the lobe does not fit the Bsdf's storage: raise kLobeSize");
    static_assert(std::is_trivially_destructible_v<Lobe>, "the Bsdf never destroys its lobes");
    if (weight.isBlack()) return;
    if (lobeCount_ == kMaxLobes) throw std::length_error("more lobes than Bsdf::kMaxLobes");
    Lobe* lobe = ::new (storage_[lobeCount_].bytes) Lobe(weight, std::forward<Args>(args)...);
    if (lobe->isDiffuse())
        diffuseWeight_ += lobe->weight();
    else if (lobe->isDelta())
        deltaLobes_[deltaCount_++] = lobe;
    else if (lobe->isRough())
        roughLobes_[roughCount_++] = lobe;
    else
        glossyLobes_[glossyCount_++] = lobe;
    lobes_[lobeCount_++] = lobe;
}

}  // namespace lancer
