#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "math/Color.h"
#include "math/Ray.h"
#include "radiosity/Element.h"
#include "radiosity/Patch.h"
#include "radiosity/RadiosityMesh.h"
#include "scene/LightSampler.h"

namespace lancer {

struct Hit;
class RadiositySolution;
class Scene;

// The light that reaches a diffuse surface through glossy reflections (the `specular`
// Blinn-Phong lobe): what a solution of diffuse transport alone leaves out (a glossy floor sends
// a lamp's light up to the ceiling). Estimated at a point by cosine-distributed rays; where one
// meets a glossy surface, that surface's reflection towards the point is estimated from one
// sample of the emitters (picked as the path tracer picks them) through the lobe's f, with a
// shadow ray, and one direction drawn from each glossy lobe, which finds the diffuse light of the
// surface it meets in a solution (kd / pi times its irradiance) and the emitters' light: the two
// techniques weighed by the power heuristic where both find an emitter, so that a sharp lobe's
// rare, very bright emitter samples do not show as blotches. Where that direction meets another
// glossy surface, its glossy reflection is estimated there the same way, and so on up to
// kLongestGlossyChain reflections.
class GlossyTransport {
public:
    // Rounds of it a solver makes, each from the solution the one before left: twice, so that
    // light reflected by a glossy surface twice is in too.
    static constexpr int kRounds = 2;
    // Glossy reflections in a row that a sample follows (a glossy floor's highlight reflected by
    // a glossy sphere onto the walls is two); the next ones carry little light.
    static constexpr int kLongestGlossyChain = 4;

    // `samples` rays per element, four times as many per vertex (which the image shows).
    GlossyTransport(const Scene& scene, int samples);

    // At each of `elements` of the mesh, from `solution` (`round` seeds the samples); the
    // rays traced are added to rayCount. Stops early once `cancel` is set.
    std::vector<std::array<Color, 2>> atElements(const RadiosityMesh& mesh,
                                                 const std::vector<std::uint32_t>& elements,
                                                 const RadiositySolution& solution, int round,
                                                 const std::atomic<bool>* cancel,
                                                 std::uint64_t& rayCount) const;
    // At the gather site of vertex `vertex`, from `solution`.
    std::array<Color, 2> atVertex(const Element& site, std::size_t vertex,
                                  const RadiositySolution& solution, std::uint64_t& rayCount) const;

private:
    // The irradiance on each side of the element at its surface point (none where it reflects
    // nothing), through one glossy reflection, from `samples` rays placed by `seed`.
    std::array<Color, 2> at(const Element& element, const RadiositySolution& solution, int samples,
                            std::uint64_t seed, std::uint64_t& rayCount) const;
    // What the first surface along the ray reflects back along it through its glossy lobes
    // (radiance), with the sample numbers that `seed` gives.
    Color glossyRadiance(const Ray& ray, const RadiositySolution& solution, std::uint64_t seed,
                         std::uint64_t& rayCount) const;
    // What `hit`'s glossy lobes reflect towards wo, the `reflections`-th glossy reflection of a
    // chain: emitters, the solution's diffuse light and, up to kLongestGlossyChain reflections,
    // the glossy light of the surfaces its lobes' samples meet.
    Color reflectedGlossily(const Hit& hit, const Vec3& wo, const RadiositySolution& solution,
                            std::uint64_t seed, int reflections, std::uint64_t& rayCount) const;

    const Scene& scene_;
    LightSampler emitters_;
    int samples_;
    float offset_;  // how far rays start off the element's surface point
};

}  // namespace lancer
