#include "render/PixelEstimator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/Integrator.h"
#include "sampling/Sampler.h"
#include "scene/Scene.h"

namespace lancer {

namespace {

double luminance(const Color& c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

// The rule of a pixel's filtered mean, for its image and its auxiliary outputs alike: the
// weights sum to about the sample count (the filter integrates to 1, so a weight is 1 on
// average). With a negative-lobed filter (Mitchell) and very few samples, positive and negative
// weights can cancel to nearly nothing (two samples, one in a lobe) and blow the pixel up; then
// the pixel is averaged with the weights' magnitudes instead. Either way it is a weighted
// average, so a constant image stays constant. For a box every weight is 1.
bool signedWeightsHold(double signedWeight, long long count) {
    return signedWeight >= 0.5 * static_cast<double>(count);
}

// Sums of weighted samples: sum(w L), sum(w y) for the luminance y, and sum(w).
struct WeightedSums {
    double r = 0, g = 0, b = 0, y = 0, weight = 0;

    void add(const Color& L, double y_, double w) {
        r += w * L.r;
        g += w * L.g;
        b += w * L.b;
        y += w * y_;
        weight += w;
    }
};

// Running sums of a pixel's weighted samples (in double: a pixel may take a million samples): the
// filtered value sum(w L) / sum(w) and the standard error of its luminance.
class WeightedMean {
public:
    void add(const Color& L, double w) {
        const double y = luminance(L);
        signed_.add(L, y, w);
        magnitude_.add(L, y, std::abs(w));
        squaredWeights_ += w * w;
        squaredWeightsY_ += w * w * y;
        squaredWeightsY2_ += w * w * y * y;
        ++count_;
    }

    // The filtered value, each channel no darker than kLobeFloor times the pixel's mean under
    // |filter|. With a negative-lobed filter (Mitchell) one bright sample in a lobe (a highlight,
    // a light in a mirror) can outweigh the pixel's own samples and make it negative, which
    // shows as a black speckle; the mean under |filter| is a plain weighted average, never
    // negative and black only where every sample is. Converged ringing seldom darkens a pixel
    // below half that mean, so the floor removes the noise and keeps the sharpening. For a
    // filter without negative lobes the two means are the same: the floor changes nothing.
    Color value() const {
        const WeightedSums& s = sums();
        const auto channel = [&](double signedSum, double magnitudeSum) {
            return static_cast<float>(
                std::max(signedSum / s.weight, kLobeFloor * magnitudeSum / magnitude_.weight));
        };
        return {channel(s.r, magnitude_.r), channel(s.g, magnitude_.g), channel(s.b, magnitude_.b)};
    }

    double luminanceValue() const { return sums().y / sums().weight; }

    // The standard error of the luminance estimate Y = sum(w y) / sum(w), from the samples'
    // spread as if they were independent (the delta method for a ratio: the variance of
    // w (y - Y), times n, over sum(w)^2). Stratified samples converge faster than that, but the
    // estimate is large exactly where the pixel is noisy (edges, soft shadows, textures), which is
    // what the stopping rule needs: it compares pixels with each other.
    double standardError() const {
        if (count_ < 2) return std::numeric_limits<double>::infinity();
        const double y = luminanceValue();
        const double spread =
            std::max(0.0, squaredWeightsY2_ - 2 * y * squaredWeightsY_ + y * y * squaredWeights_);
        const double n = static_cast<double>(count_);
        return std::sqrt(spread * n / (n - 1)) / sums().weight;
    }

private:
    const WeightedSums& sums() const {
        return signedWeightsHold(signed_.weight, count_) ? signed_ : magnitude_;
    }

    static constexpr double kLobeFloor = 0.5;

    WeightedSums signed_, magnitude_;
    double squaredWeights_ = 0, squaredWeightsY_ = 0, squaredWeightsY2_ = 0;
    long long count_ = 0;
};

// The filtered mean of a pixel's AovSamples, by the image's rule (signedWeightsHold).
class AovMean {
public:
    void add(const AovSample& sample, double w) {
        signed_.add(sample, w);
        magnitude_.add(sample, std::abs(w));
        ++count_;
    }

    AovSample value() const {
        return (signedWeightsHold(signed_.weight, count_) ? signed_ : magnitude_).mean();
    }

private:
    struct Sums {
        double albedo[3] = {}, normal[3] = {}, depth = 0, weight = 0;

        void add(const AovSample& s, double w) {
            albedo[0] += w * s.albedo.r;
            albedo[1] += w * s.albedo.g;
            albedo[2] += w * s.albedo.b;
            normal[0] += w * s.normal.x;
            normal[1] += w * s.normal.y;
            normal[2] += w * s.normal.z;
            depth += w * s.depth;
            weight += w;
        }
        AovSample mean() const {
            const auto f = [&](double sum) { return static_cast<float>(sum / weight); };
            return {{f(albedo[0]), f(albedo[1]), f(albedo[2])},
                    {f(normal[0]), f(normal[1]), f(normal[2])},
                    f(depth)};
        }
    };

    Sums signed_, magnitude_;
    long long count_ = 0;
};

}  // namespace

PixelEstimator::PixelEstimator(const Scene& scene, const Integrator& integrator)
    : scene_(scene),
      integrator_(integrator),
      firstHitProbe_(scene),
      filterSampler_(Filter::create(scene.settings().filter)),
      maxSamples_(scene.settings().samplesPerPixel),
      lightEdgeSamples_(static_cast<int>(std::min<long long>(
          static_cast<long long>(maxSamples_) * std::max(scene.settings().lightEdgeFactor, 1),
          RenderSettings::kMaxSamplesPerPixel))) {
    const std::optional<AdaptiveSettings>& adaptive = scene.settings().adaptive;
    batchSize_ = adaptive ? std::min(adaptive->minSamples, maxSamples_) : 0;
    threshold_ = adaptive ? adaptive->threshold : 0.0;
}

Color PixelEstimator::estimate(int x, int y, std::uint64_t seed, RenderCounters& counters,
                               bool onLightEdge, AovSample* aovs) const {
    const RenderSettings& settings = scene_.settings();
    const Camera& camera = scene_.camera();
    // Each of n samples covers about 1/sqrt(n) of the pixel's width (n: the most samples the pixel
    // may take); the floor keeps some texture filtering at very high counts (as pbrt does).
    const RayCone footprint =
        camera.pixelCone(settings.width, settings.height)
            .scaled(std::max(0.125f, 1 / std::sqrt(static_cast<float>(maxSamples_))));
    Sampler sampler(seed, x, y);
    WeightedMean mean;
    AovMean aovMean;
    const int maxSamples = onLightEdge ? lightEdgeSamples_ : maxSamples_;
    const int batchSize = batchSize_ > 0 ? batchSize_ : maxSamples;
    int n = 0;
    for (int target = batchSize;; target = std::min(target + batchSize, maxSamples)) {
        for (; n < target; ++n) {
            sampler.startSample(n);
            // A single sample goes through the pixel centre, as a classic ray tracer's: its
            // filter point keeps its place among the requests, undrawn.
            FilterSample film{{0, 0}, 1};
            if (maxSamples == 1)
                sampler.skip();
            else
                film = filterSampler_.sample(sampler.get2D());
            // A pinhole's lens sample keeps its place among the requests, undrawn.
            Vec2 lens;
            if (camera.usesLensSample())
                lens = sampler.get2D();
            else
                sampler.skip();
            const std::optional<Ray> ray =
                camera.generateRay(static_cast<float>(x) + 0.5f + film.offset.x,
                                   static_cast<float>(y) + 0.5f + film.offset.y, settings.width,
                                   settings.height, lens);
            // Where the camera sees nothing (outside a fisheye's circle) the sample is black.
            if (!ray) {
                mean.add(Color(), film.weight);
                if (aovs) aovMean.add(AovSample{}, film.weight);
                continue;
            }
            Color L = integrator_.radiance(*ray, footprint, sampler, counters.rays);
            // One NaN or infinity would spoil the pixel for good: the sample counts as black
            // (as pbrt does), and is counted for --stats.
            if (!L.isFinite()) {
                ++counters.nonFiniteSamples;
                L = Color();
            }
            if (settings.sampleClamp && L.maxComponent() > *settings.sampleClamp)
                L = L * (*settings.sampleClamp / L.maxComponent());
            mean.add(L, film.weight);
            if (aovs) aovMean.add(firstHitProbe_.probe(*ray, counters.rays), film.weight);
        }
        if (n >= maxSamples) break;
        // The error is relative to the pixel's luminance, so that the threshold means the same
        // in bright and dim parts of the image; but below kDarkLuminanceFloor (a quarter of the
        // display's range once sRGB-encoded), relative to the floor. Without it a nearly black
        // pixel, whose relative error is large but invisible, would always take max_spp; a
        // dark pixel that some samples find bright (a gap onto a light) still has a large error
        // against the floor and is not starved.
        const double scale = std::max(mean.luminanceValue(), kDarkLuminanceFloor);
        if (mean.standardError() <= threshold_ * scale) break;
    }
    counters.samples += static_cast<std::uint64_t>(n);
    ++counters.pixels;
    if (aovs) *aovs = aovMean.value();
    return mean.value();
}

}  // namespace lancer
