#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "radiosity/FormFactor.h"
#include "radiosity/GlossyTransport.h"
#include "radiosity/RadiosityMesh.h"
#include "radiosity/RadiosityMethod.h"
#include "radiosity/RadiosityProgress.h"
#include "radiosity/RadiositySolution.h"
#include "radiosity/SplitIrradiance.h"
#include "radiosity/VertexSmoothing.h"
#include "scene/RadiositySettings.h"

namespace lancer {

class Scene;

// Progressive refinement radiosity (Cohen, Chen, Wallace and Greenberg 1988) over the scene's
// patches and elements (PatchMesher):
//  1. emissive patches start with their emitted radiosity unshot; the scene's lights (point,
//     directional, spot, area) light every element first, through Light::sample with shadow rays,
//     and what the elements reflect becomes their unshot radiosity;
//  2. the patch side with the most unshot power shoots it to every element, each of its own
//     elements shooting its share from where it is (form factors by ray casting, FormFactor), in
//     parallel over the receiving elements, until the unshot power left is below the threshold
//     times the power put in;
//  3. adaptive subdivision: an element whose irradiance differs from its corners' (the average of
//     the elements around them) by more than the tolerance is split in four, and the children
//     gather again from the lights and from the radiosity every shooting element has shot;
//     repeated per level;
//  4. the irradiance at every corner of the final elements is gathered there (from the lights
//     and everything shot), for the image's interpolation.
// The result does not depend on the number of threads: each element's share of a shot is
// computed on its own, from seeds of (patch, element), and added in element order.
class ProgressiveRadiosity : public RadiosityMethod {
public:
    explicit ProgressiveRadiosity(const Scene& scene);

    // Over the patches (geometry, reflectance, emission), the lights and the radiosity settings.
    std::uint64_t fingerprint() const override { return fingerprint_; }
    const RadiosityMesh& mesh() const { return mesh_; }

    RadiositySolution solve();
    // The same solve, reporting to `onProgress` (if any) on the solving thread between its steps:
    // before the first shot, after each shot, before each subdivision level and before the
    // final gather. The solution is the same with or without it (it may call snapshot(), which
    // changes nothing). Once `cancel` (if any) is set, the solve stops within a fraction of a
    // shot and returns nothing; the solver is then not to be used again.
    std::optional<RadiositySolution> solve(
        const std::function<void(const RadiosityProgress&)>& onProgress,
        const std::atomic<bool>* cancel) override;
    // The solution as it stands, for a preview during the solve (from onProgress): the leaves'
    // irradiance averaged at their corners, without the final gather.
    RadiositySolution snapshot() const override;

    // The unshot power (W, mean over r, g, b) before the first shot and after each one.
    const std::vector<double>& unshotHistory() const { return unshotHistory_; }

private:
    void lightElements();
    // Shoots until the unshot power is below the threshold (or the shots run out); false once
    // cancelled.
    bool shootUntilConverged(const std::vector<std::uint32_t>& receivers,
                             const std::function<bool(RadiosityProgress::Phase)>& carryOn);
    // Adds to the receivers the light through glossy reflections (GlossyTransport) that the
    // solution as it stands gives beyond the last round's, and makes it unshot radiosity.
    void gatherThroughGlossy(const std::vector<std::uint32_t>& receivers, int round);
    // Shoots a patch side's unshot radiosity to the receivers, with `rays` rays per receiver
    // (shared among the patch's elements).
    void shoot(std::uint32_t patch, Side side, int rays,
               const std::vector<std::uint32_t>& receivers);
    // Splits the leaves of `level` whose irradiance jumps; returns how many were split.
    std::size_t subdivide(int level);
    // An element's irradiance gathered again: lights, then every shooting element's shot
    // radiosity; and its part straight from the sampled emitters. `key` seeds its sample points.
    SplitIrradiance gather(const Element& element, std::uint64_t key,
                           std::uint64_t& rayCount) const;
    std::array<Color, 2> lightIrradiance(const Element& element, std::uint64_t key,
                                         std::uint64_t& rayCount) const;

    // Corners closer than this are one vertex (VertexSmoothing).
    double weldingCell() const { return 1e-5 * patchSize_; }
    // Replaces the vertices' averages by irradiance gathered at the vertices themselves.
    void gatherAtVertices(VertexSmoothing& smoothing);
    bool cancelled() const { return cancel_ && cancel_->load(std::memory_order_relaxed); }
    const Scene& scene_;
    RadiositySettings settings_;
    float patchSize_;
    RadiosityMesh mesh_;
    FormFactor formFactor_;
    std::uint64_t fingerprint_ = 0;
    std::vector<double> unshotHistory_;
    std::optional<GlossyTransport> glossy_;  // where the scene has glossy surfaces
    // Per element, the irradiance through glossy reflections received so far.
    std::vector<std::array<Color, 2>> fromGlossy_;
    double initialPower_ = 0;  // the unshot power before the first shot
    std::uint64_t rays_ = 0;
    std::uint64_t shots_ = 0;
    const std::atomic<bool>* cancel_ = nullptr;  // the solve's, while it runs
};

}  // namespace lancer
