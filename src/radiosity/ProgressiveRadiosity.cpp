#include "radiosity/ProgressiveRadiosity.h"

#include <atomic>
#include <cmath>

#include "geometry/Shape.h"
#include "lights/Light.h"
#include "radiosity/LightIrradiance.h"
#include "radiosity/PatchMesher.h"
#include "radiosity/RadiosityReporter.h"
#include "radiosity/SplitIrradiance.h"
#include "radiosity/SurfaceProbe.h"
#include "radiosity/VertexSmoothing.h"
#include "sampling/StratifiedPoint.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"
#include "util/ParallelFor.h"

namespace lancer {

namespace {

// A shot carrying at least this fraction of the power put in traces all its visibility rays.
constexpr double kStrongShot = 1e-3;

// How far the receivers' form factors to a shooting element may add up beyond reciprocity's bound
// (see shoot).
constexpr double kMostTaken = 1.1;

// Stratified samples per area light when lighting elements (more if the light asks for more).
constexpr int kAreaLightSamples = 16;

}  // namespace

ProgressiveRadiosity::ProgressiveRadiosity(const Scene& scene)
    : scene_(scene), settings_(scene.settings().radiosity), patchSize_(0), formFactor_(scene) {
    const PatchMesher mesher(scene, settings_);
    patchSize_ = mesher.patchSize();
    mesh_ = mesher.mesh();

    fingerprint_ = mesh_.fingerprint(scene, settings_);
    if (scene.hasGlossyMaterial() && settings_.glossySamples > 0)
        glossy_.emplace(scene, settings_.glossySamples);
}

std::array<Color, 2> ProgressiveRadiosity::lightIrradiance(const Element& e, std::uint64_t key,
                                                           std::uint64_t& rayCount) const {
    std::array<Color, 2> E;
    if (scene_.lights().empty()) return E;
    for (Side side : kBothSides)
        E[sideIndex(side)] =
            LightIrradiance::at(scene_, e.surfacePoint, e.surfaceNormal, e.surfaceSideNormal(side),
                                kAreaLightSamples, hashValues(key, sideIndex(side)), rayCount);
    return E;
}

void ProgressiveRadiosity::lightElements() {
    const std::vector<std::uint32_t> leaves = mesh_.leaves();
    std::vector<std::array<Color, 2>> E(leaves.size());
    rays_ +=
        parallelForCounting(leaves.size(), 16, cancel_, [&](std::size_t i, std::uint64_t& rays) {
            E[i] = lightIrradiance(mesh_.elements[leaves[i]], leaves[i], rays);
        });
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        Element& e = mesh_.elements[leaves[i]];
        Patch& patch = mesh_.patches[e.patch];
        for (std::size_t side = 0; side < 2; ++side) {
            e.irradiance[side] += E[i][side];
            e.unshot[side] += e.reflectance * E[i][side];
            patch.unshot[side] += e.reflectance * E[i][side] * (e.area / patch.area);
        }
    }
}

void ProgressiveRadiosity::shoot(std::uint32_t shooter, Side side, int rays,
                                 const std::vector<std::uint32_t>& receivers) {
    Patch& patch = mesh_.patches[shooter];
    const std::size_t s = sideIndex(side);
    // Each element of the patch shoots its own unshot radiosity, with its share of the rays.
    struct Shot {
        std::uint32_t element;
        Color radiosity;
    };
    std::vector<Shot> shots;
    for (std::uint32_t k = patch.firstElement; k < patch.firstElement + patch.elementCount; ++k) {
        Element& e = mesh_.elements[k];
        if (e.unshot[s].isBlack()) continue;
        shots.push_back({k, e.unshot[s]});
        e.shot[s] += e.unshot[s];
        e.unshot[s] = Color(0);
    }
    patch.unshot[s] = Color(0);
    const int raysEach = std::max(1, rays / static_cast<int>(patch.elementCount));
    // F from each receiver side to each shooting element: formFactors[(i * 2 + r) * n + k].
    const std::size_t n = shots.size();
    std::vector<Color> formFactors(receivers.size() * 2 * n);
    rays_ += parallelForCounting(
        receivers.size(), 16, cancel_, [&](std::size_t i, std::uint64_t& rayCount) {
            const std::uint32_t e = receivers[i];
            const Element& element = mesh_.elements[e];
            if (element.patch == shooter) return;  // flat: it cannot see itself
            for (Side r : kBothSides)
                for (std::size_t k = 0; k < n; ++k)
                    formFactors[(i * 2 + sideIndex(r)) * n + k] = formFactor_.elementToTriangle(
                        element, r, mesh_.elements[shots[k].element].corners, patch, side, raysEach,
                        hashValues(shots[k].element, s, e, sideIndex(r)), rayCount);
        });
    // A form factor taken at the receiver's centroid stands for its whole area: a large receiver
    // close to a small shooter (a ceiling just above a lamp's back) can then take in more than
    // the shooter sends. Reciprocity bounds what all receivers take, sum A_j F_jk <= A_k. Sums
    // a little above (the quadrature's error near corners) are left alone, so that closed rooms
    // keep their energy; a sum beyond kMostTaken times is scaled back to A_k, so that no
    // shot creates power (rho kMostTaken < 1 for any albedo below 0.9) and the solve converges.
    std::vector<float> scale(n, 1);
    for (std::size_t k = 0; k < n; ++k) {
        double taken = 0;
        for (std::size_t i = 0; i < receivers.size(); ++i)
            for (std::size_t r = 0; r < 2; ++r)
                taken += static_cast<double>(formFactors[(i * 2 + r) * n + k].maxComponent()) *
                         mesh_.elements[receivers[i]].area;
        const double sent = mesh_.elements[shots[k].element].area;
        if (taken > kMostTaken * sent) scale[k] = static_cast<float>(sent / taken);
    }
    for (std::size_t i = 0; i < receivers.size(); ++i) {
        Element& e = mesh_.elements[receivers[i]];
        Patch& target = mesh_.patches[e.patch];
        for (std::size_t r = 0; r < 2; ++r) {
            Color received;
            for (std::size_t k = 0; k < n; ++k)
                received += shots[k].radiosity * formFactors[(i * 2 + r) * n + k] * scale[k];
            e.irradiance[r] += received;
            e.unshot[r] += e.reflectance * received;
            target.unshot[r] += e.reflectance * received * (e.area / target.area);
        }
    }
}

SplitIrradiance ProgressiveRadiosity::gather(const Element& e, std::uint64_t key,
                                             std::uint64_t& rayCount) const {
    SplitIrradiance E;
    E.direct = lightIrradiance(e, key, rayCount);
    E.total = E.direct;
    for (std::uint32_t i = 0; i < mesh_.patches.size(); ++i) {
        if (i == e.patch) continue;
        const Patch& patch = mesh_.patches[i];
        // What a render samples of the patch's emission: a patch that emits shot all of it with
        // its first shot, so it is part of what it shot.
        const bool sampled = patch.surface->isBounded();
        for (std::uint32_t k = patch.firstElement; k < patch.firstElement + patch.elementCount;
             ++k) {
            const Element& shooter = mesh_.elements[k];
            for (Side s : kBothSides) {
                const Color& shot = shooter.shot[sideIndex(s)];
                if (shot.isBlack()) continue;
                const Color emitted = sampled ? kPi * patch.emission[sideIndex(s)] : Color(0);
                // Shooters that shot much (the emitters, the brightest walls) make the shadows
                // that show: they get all the rays.
                const int raysEach = shot.average() * shooter.area >= kStrongShot * initialPower_
                                         ? settings_.visibilityRays
                                         : 1;
                for (Side r : kBothSides) {
                    const Color formFactor = formFactor_.elementToTriangle(
                        e, r, shooter.corners, patch, s, raysEach,
                        hashValues(k, sideIndex(s), key, sideIndex(r)), rayCount);
                    E.total[sideIndex(r)] += shot * formFactor;
                    E.direct[sideIndex(r)] += emitted * formFactor;
                }
            }
        }
    }
    return E;
}

std::size_t ProgressiveRadiosity::subdivide(int level) {
    const std::vector<std::uint32_t> leaves = mesh_.leaves();
    const VertexSmoothing smoothing(mesh_, leaves, weldingCell());
    float brightest = 0;
    for (std::uint32_t e : leaves)
        for (const Color& c : mesh_.elements[e].irradiance)
            brightest = std::max(brightest, c.average());
    // Differences among the darkest elements do not show.
    const float floor = 1e-3f * brightest;
    std::vector<std::uint32_t> children, parentOf;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        const Element& e = mesh_.elements[leaves[i]];
        if (e.level != level) continue;
        bool jumps = false;
        for (std::size_t side = 0; side < 2 && !jumps; ++side)
            for (std::uint32_t v : smoothing.faceVertices[i]) {
                const float here = e.irradiance[side].average();
                const float there = smoothing.vertexIrradiance[v][side].average();
                const float larger = std::max(here, there);
                if (larger > floor &&
                    std::abs(here - there) > settings_.subdivisionTolerance * larger)
                    jumps = true;
            }
        if (!jumps) continue;
        const std::uint32_t first = mesh_.split(leaves[i]);
        for (std::uint32_t c = first; c < first + 4; ++c) {
            children.push_back(c);
            parentOf.push_back(leaves[i]);
        }
    }
    for (std::uint32_t c : children) {
        Element& child = mesh_.elements[c];
        SurfaceProbe::place(mesh_.patches[child.patch], child.corners, child);
    }
    std::vector<std::array<Color, 2>> E(children.size());
    rays_ +=
        parallelForCounting(children.size(), 16, cancel_, [&](std::size_t i, std::uint64_t& rays) {
            E[i] = gather(mesh_.elements[children[i]], children[i], rays).total;
        });
    // The light through glossy reflections is not gathered again: the children take their
    // parent's (the vertices gather it at the end).
    fromGlossy_.resize(mesh_.elements.size());
    for (std::size_t i = 0; i < children.size(); ++i) {
        fromGlossy_[children[i]] = fromGlossy_[parentOf[i]];
        for (std::size_t side = 0; side < 2; ++side)
            E[i][side] += fromGlossy_[children[i]][side];
        mesh_.elements[children[i]].irradiance = E[i];
    }
    return children.size() / 4;
}

void ProgressiveRadiosity::gatherAtVertices(VertexSmoothing& smoothing) {
    const auto key = static_cast<std::uint64_t>(mesh_.elements.size());
    const std::optional<RadiositySolution> current =
        glossy_ ? std::optional<RadiositySolution>(snapshot()) : std::nullopt;
    rays_ += parallelForCounting(smoothing.vertexIrradiance.size(), 16, cancel_,
                                 [&](std::size_t v, std::uint64_t& rays) {
                                     const Element site = smoothing.gatherSite(scene_, v, rays);
                                     SplitIrradiance E = gather(site, key + v, rays);
                                     if (glossy_)
                                         E += {glossy_->atVertex(site, v, *current, rays), {}};
                                     smoothing.vertexIrradiance[v] = E.total;
                                     smoothing.vertexDirect[v] = E.direct;
                                 });
}

RadiositySolution ProgressiveRadiosity::solve() {
    return *solve({}, nullptr);
}

bool ProgressiveRadiosity::shootUntilConverged(
    const std::vector<std::uint32_t>& receivers,
    const std::function<bool(RadiosityProgress::Phase)>& carryOn) {
    const double initial = initialPower_;
    while (initial > 0 && unshotHistory_.back() > settings_.threshold * initial &&
           shots_ < static_cast<std::uint64_t>(settings_.maxShots)) {
        std::uint32_t best = 0;
        Side bestSide = Side::Front;
        float most = -1;
        for (std::uint32_t i = 0; i < mesh_.patches.size(); ++i)
            for (Side s : kBothSides) {
                const float power =
                    mesh_.patches[i].unshot[sideIndex(s)].average() * mesh_.patches[i].area;
                if (power > most) {
                    most = power;
                    best = i;
                    bestSide = s;
                }
            }
        // The many weak shots of the end carry little light each: one ray is enough for their
        // visibility (Wallace et al. 1989 likewise scale the rays with the shooter's power).
        const bool strong = most >= kStrongShot * initial;
        shoot(best, bestSide, strong ? settings_.visibilityRays : 1, receivers);
        ++shots_;
        unshotHistory_.push_back(mesh_.unshotPower().average());
        if (!carryOn(RadiosityProgress::Phase::Shooting)) return false;
    }

    return true;
}

void ProgressiveRadiosity::gatherThroughGlossy(const std::vector<std::uint32_t>& receivers,
                                               int round) {
    const std::vector<std::array<Color, 2>> E =
        glossy_->atElements(mesh_, receivers, snapshot(), round, cancel_, rays_);
    // What is new since the last round is received, and reflected as unshot radiosity.
    for (std::size_t i = 0; i < receivers.size(); ++i) {
        Element& e = mesh_.elements[receivers[i]];
        Patch& patch = mesh_.patches[e.patch];
        for (std::size_t side = 0; side < 2; ++side) {
            const Color added = E[i][side] - fromGlossy_[receivers[i]][side];
            fromGlossy_[receivers[i]][side] = E[i][side];
            e.irradiance[side] += added;
            e.unshot[side] += e.reflectance * added;
            patch.unshot[side] += e.reflectance * added * (e.area / patch.area);
        }
    }
    unshotHistory_.push_back(mesh_.unshotPower().average());
}

std::optional<RadiositySolution> ProgressiveRadiosity::solve(
    const std::function<void(const RadiosityProgress&)>& onProgress,
    const std::atomic<bool>* cancel) {
    cancel_ = cancel;
    const RadiosityReporter reporter(onProgress, cancel);
    const auto carryOn = [&](RadiosityProgress::Phase phase) {
        return reporter.carryOn(phase, shots_, unshotHistory_.back(), initialPower_);
    };

    for (Patch& p : mesh_.patches)
        for (std::size_t side = 0; side < 2; ++side) {
            p.unshot[side] = kPi * p.emission[side];  // B = pi L for a Lambertian emitter
            for (std::uint32_t k = p.firstElement; k < p.firstElement + p.elementCount; ++k)
                mesh_.elements[k].unshot[side] = p.unshot[side];
        }
    lightElements();
    fromGlossy_.assign(mesh_.elements.size(), {});

    const std::vector<std::uint32_t> receivers = mesh_.leaves();
    const double initial = mesh_.unshotPower().average();
    initialPower_ = initial;
    unshotHistory_ = {initial};
    shots_ = 0;
    if (!carryOn(RadiosityProgress::Phase::Shooting)) return std::nullopt;
    if (!shootUntilConverged(receivers, carryOn)) return std::nullopt;
    // The light through glossy reflections, from the solution as it stands, shot on with the
    // rest; twice, so that it is itself reflected by the glossy surfaces.
    if (glossy_)
        for (int round = 0; round < GlossyTransport::kRounds; ++round) {
            gatherThroughGlossy(receivers, round);
            if (cancelled() || !shootUntilConverged(receivers, carryOn)) return std::nullopt;
        }

    for (int level = 0; level < settings_.subdivisionLevels; ++level) {
        if (!carryOn(RadiosityProgress::Phase::Subdividing)) return std::nullopt;
        if (subdivide(level) == 0) break;
    }

    if (!carryOn(RadiosityProgress::Phase::Gathering)) return std::nullopt;
    const std::vector<std::uint32_t> leaves = mesh_.leaves();
    VertexSmoothing smoothing(mesh_, leaves, weldingCell());
    gatherAtVertices(smoothing);
    if (cancelled()) return std::nullopt;

    RadiosityStatistics statistics;
    statistics.patches = mesh_.patches.size();
    statistics.elements = leaves.size();
    statistics.shots = shots_;
    statistics.initialPower = initial;
    statistics.residualPower = unshotHistory_.back();
    statistics.rays = rays_;
    statistics.seconds = reporter.seconds();
    return std::move(smoothing).solution(mesh_.lookupDistance(patchSize_), fingerprint_,
                                         statistics);
}

RadiositySolution ProgressiveRadiosity::snapshot() const {
    const std::vector<std::uint32_t> leaves = mesh_.leaves();
    RadiosityStatistics statistics;
    statistics.patches = mesh_.patches.size();
    statistics.elements = leaves.size();
    statistics.shots = shots_;
    statistics.initialPower = initialPower_;
    statistics.residualPower = unshotHistory_.empty() ? 0 : unshotHistory_.back();
    statistics.rays = rays_;
    return VertexSmoothing(mesh_, leaves, weldingCell())
        .solution(mesh_.lookupDistance(patchSize_), fingerprint_, statistics);
}

}  // namespace lancer
