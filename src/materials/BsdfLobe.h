#pragma once

#include <array>
#include <cstddef>
#include <optional>

#include "materials/BsdfSample.h"
#include "materials/SpecularRay.h"
#include "materials/SpecularSplit.h"
#include "math/Vec2.h"

namespace lancer {

// One scattering lobe of a BSDF, in the local shading frame: z is the shading normal on the
// surface's outer (front) side, directions are unit vectors pointing away from the surface.
//
// A lobe has a weight, the colour that bounds its albedo (kd, ks, kr, kt), which the Bsdf sums
// for its energy scale and its choice of lobe. Lobes live in a Bsdf's inline storage, which never
// destroys them: they must be trivially destructible, hence the protected, non-virtual destructor.
class BsdfLobe {
public:
    // What a lobe is, fixed by its class: asked at every hit, so kept as data, not virtual.
    enum class Kind {
        Diffuse,  // ideal diffuse, f = weight / pi (local response weight cos theta_L): the
                  // light radiosity computes
        Glossy,   // any other lobe with a density: highlights (radiosity also gathers along
                  // a direction sampled from it)
        Delta,    // scatters into single directions (mirror, smooth glass): f() and pdf() are 0
                  // and only sample() finds them
        Rough,    // a microfacet lobe with a density about the mirror and refracted directions
                  // (rough metal and glass): Whitted and radiosity trace its tracedRays(), and
                  // shade only point-like lights with its f() (a traced ray finds the rest)
    };
    bool isDelta() const { return kind_ == Kind::Delta; }
    bool isDiffuse() const { return kind_ == Kind::Diffuse; }
    bool isRough() const { return kind_ == Kind::Rough; }
    virtual Color f(const Vec3& wo, const Vec3& wi) const = 0;
    virtual float pdf(const Vec3& wo, const Vec3& wi) const = 0;
    // A direction for wo from u in [0,1)^2 (and uChoice in [0,1), for a lobe that also chooses
    // between reflection and refraction), or none when the lobe has nothing to give. A non-delta
    // lobe's sample holds its own f() and pdf() for the direction (a Bsdf of that lobe alone
    // takes them as they are).
    virtual std::optional<BsdfSample> sample(const Vec3& wo, float uChoice,
                                             const Vec2& u) const = 0;
    // Whether sample() reads uChoice.
    virtual bool readsChoice() const { return false; }

    // The classic local model that Whitted shades with, next to the physical f(), for a glossy
    // lobe (the Bsdf gives a diffuse lobe's kd cos(theta_L) itself; Whitted traces a delta
    // lobe's light instead): the light reflected towards the viewer per unit of a light's
    // irradiance E_l, for the light at cosThetaL > 0 from the shading normal on the viewer's side
    // and the half vector of light and viewer at cosThetaH.
    virtual Color localResponse(float /*cosThetaL*/, float /*cosThetaH*/) const { return Color(0); }
    // How a delta lobe splits the light from a viewer at cosThetaO (>= 0) from the shading normal
    // on its side, on the front side or not (outside). Nothing for other lobes.
    virtual SpecularSplit specularSplit(float /*cosThetaO*/, bool /*outside*/) const { return {}; }
    // Whitted's distribution ray tracing of a rough lobe: the directions to trace from wo, drawn
    // with u (one microfacet normal: its reflection and its refraction), each with the weight
    // f cos / pdf of its radiance (a refraction without the 1 / eta^2, as Whitted's smooth glass).
    // Returns how many were written. Nothing for other lobes.
    virtual std::size_t tracedRays(const Vec3& /*wo*/, const Vec2& /*u*/,
                                   std::array<SpecularRay, 2>& /*rays*/) const {
        return 0;
    }

    const Color& weight() const { return weight_; }
    // Multiplies the weight by s, for energy conservation.
    void scaleWeight(float s) { weight_ *= s; }

protected:
    BsdfLobe(const Color& weight, Kind kind) : weight_(weight), kind_(kind) {}
    BsdfLobe(const BsdfLobe&) = default;
    BsdfLobe& operator=(const BsdfLobe&) = default;
    ~BsdfLobe() = default;

private:
    Color weight_;
    Kind kind_;
};

}  // namespace lancer
