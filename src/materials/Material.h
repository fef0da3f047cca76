#pragma once

#include <memory>
#include <utility>

#include "materials/ShadingNormalMap.h"
#include "math/Color.h"
#include "math/Vec3.h"

namespace lancer {

class Bsdf;
class Texture;
struct Hit;

// How a surface interacts with light: the BSDF its implementation builds at a hit, and the
// properties that the integrators and the radiosity solver ask for besides the lobes.
class Material {
public:
    virtual ~Material() = default;

    // Adds the lobes of the BSDF at the hit (called while the Bsdf is built).
    virtual void addLobes(const Hit& hit, Bsdf& bsdf) const = 0;

    // The albedo of the ideal diffuse reflection at the hit (kd): what radiosity spreads.
    virtual Color diffuseReflectance(const Hit& hit) const = 0;
    // Whether diffuseReflectance can be other than black anywhere, which decides whether the
    // radiosity solver meshes the surface.
    virtual bool reflectsDiffusely() const = 0;
    // Whether the BSDF can have a glossy lobe (Bsdf::glossyLobeCount), whose reflection of the
    // diffuse surfaces radiosity's glossy transport follows.
    virtual bool reflectsGlossily() const { return false; }
    // Whitted's ambient coefficient ka at the hit, which multiplies the scene's ambient light.
    virtual Color ambientReflectance(const Hit& hit) const { return diffuseReflectance(hit); }
    // The radiance emitted at the hit (a Lambertian emitter), and its mean over the surface (the
    // same where the emission is uniform): what decides whether the surface emits at all and how
    // much power it has.
    virtual Color emission(const Hit&) const { return emission(); }
    virtual Color emission() const { return Color(0); }
    // Whether emission(hit) varies over the surface (lights then look it up at their samples).
    virtual bool hasTexturedEmission() const { return false; }
    // The fraction kt of light that passes straight through (what shadow rays through glass
    // keep); black for an opaque material.
    virtual Color transmission() const { return Color(0); }

    bool isTransmissive() const { return !transmission().isBlack(); }

    // The map that perturbs the shading normal of every material type (normal or bump map);
    // null for none.
    void setShadingNormalMap(std::shared_ptr<const ShadingNormalMap> map) {
        shadingNormalMap_ = std::move(map);
    }
    // The normal of the BSDF's frame at the hit, seen from wo: hit.ns, or the map's normal, which
    // is bent back to just above the horizon where it would face away from the viewer (a
    // surface seen from behind its normal would be black).
    Vec3 shadingNormal(const Hit& hit, const Vec3& wo) const;

    // The coverage of every material type (an alpha cut-out: leaves, fences), looked up at each
    // hit: where its value (the mean of its channels) is below 1/2 the surface is cut away, and
    // rays pass straight through as if it were not there. Null for none.
    void setOpacity(std::shared_ptr<const Texture> opacity) { opacity_ = std::move(opacity); }
    bool hasCutOuts() const { return opacity_ != nullptr; }
    bool isCutAway(const Hit& hit) const;

    // Whether a look-up at a hit reads its uv footprint (a filtered image texture, a bump map):
    // Whitted computes the footprint of the hits of those materials only.
    bool readsFootprint() const;

protected:
    // For an implementation whose own textures read the footprint (said once, when it is made).
    void setTexturesReadFootprint(bool read) { texturesReadFootprint_ = read; }

private:
    std::shared_ptr<const ShadingNormalMap> shadingNormalMap_;
    std::shared_ptr<const Texture> opacity_;
    bool texturesReadFootprint_ = false;
};

}  // namespace lancer
