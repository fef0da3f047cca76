// The conductors and the GGX microfacet lobes (rough metal and glass): their sampling follows
// their pdf (a chi-square test over the sphere in equal-area (cos theta, phi) cells, as Mitsuba's
// chi2 test, at several roughnesses and incidence angles), the pdf integrates to at most 1, f is
// reciprocal, a rough mirror of Fresnel 1 reflects no more than it receives and loses what the
// single-scattering model is known to lose, the conductor Fresnel term meets its closed forms,
// the named metals' colours at normal incidence are the table's, roughness 0 is the smooth lobes
// of before, and the Bsdf lets a rough refraction through the geometric surface.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <complex>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "DirectionChiSquare.h"
#include "geometry/Hit.h"
#include "materials/BlinnPhongMaterial.h"
#include "materials/Bsdf.h"
#include "materials/ConductorLobe.h"
#include "materials/ConstantTexture.h"
#include "materials/GgxDistribution.h"
#include "materials/Optics.h"
#include "materials/RoughConductorLobe.h"
#include "materials/RoughDielectricLobe.h"
#include "math/Float.h"

namespace lancer::test {
namespace {

constexpr float kIor = 1.5f;
const ConductorIor kGold = {{0.1430f, 0.3753f, 1.4420f}, {3.9830f, 2.3856f, 1.6034f}};

// The chi-square tests of this file: the suite's 1% false-alarm rate shared among them
// (Bonferroni), 1 000 000 fixed-seed samples each, in 32 x 64 cells of equal solid angle.
constexpr int kChiSquareTests = 40;
constexpr SphereGrid kGrid{.thetaCells = 32, .phiCells = 64, .subCells = 32, .equalCosTheta = true};

void expectSamplingFollowsPdf(const BsdfLobe& lobe, const Vec3& wo, unsigned seed) {
    const DirectionSampler sampler{
        [&lobe, wo](UniformSource& random) -> std::optional<Vec3> {
            const float uChoice = random.next();
            const auto s = lobe.sample(wo, uChoice, random.next2D());
            if (!s) return std::nullopt;
            return s->wi;
        },
        [&lobe, wo](const Vec3& wi) { return static_cast<double>(lobe.pdf(wo, wi)); }};
    std::string problem;
    const double p = chiSquarePValue(sampler, 1'000'000, seed, problem, kGrid);
    EXPECT_TRUE(problem.empty()) << problem;
    EXPECT_GT(p, 0.01 / kChiSquareTests) << "the sampled directions do not follow pdf()";
}

struct RoughCase {
    std::string name;
    bool dielectric;
    float alpha;
    float woTheta;  // degrees from the normal; > 90 from the back side (inside the glass)
};

class RoughSampling : public testing::TestWithParam<RoughCase> {};

TEST_P(RoughSampling, DirectionsFollowThePdf) {
    const RoughCase& c = GetParam();
    const RoughConductorLobe conductor(Color(1), c.alpha, kGold);
    const RoughDielectricLobe dielectric(Color(1), kIor, c.alpha);
    const BsdfLobe& lobe = c.dielectric ? static_cast<const BsdfLobe&>(dielectric) : conductor;
    expectSamplingFollowsPdf(lobe, direction(c.woTheta, 20),
                             static_cast<unsigned>(c.woTheta * 100 + c.alpha * 1000));
}

std::vector<RoughCase> roughCases() {
    std::vector<RoughCase> cases;
    for (const float alpha : {0.1f, 0.3f, 0.6f, 1.0f}) {
        const std::string a = std::to_string(static_cast<int>(alpha * 100 + 0.5f));
        for (const float theta : {0.0f, 45.0f, 80.0f, 130.0f})
            cases.push_back(
                {"ConductorAlpha" + a + "Theta" + std::to_string(static_cast<int>(theta)), false,
                 alpha, theta});
        for (const float theta : {0.0f, 45.0f, 80.0f, 120.0f, 160.0f})
            cases.push_back(
                {"DielectricAlpha" + a + "Theta" + std::to_string(static_cast<int>(theta)), true,
                 alpha, theta});
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Lobes, RoughSampling, testing::ValuesIn(roughCases()),
                         [](const testing::TestParamInfo<RoughCase>& test) {
                             return test.param.name;
                         });

// The integral of g(w) over the sphere, by the midpoint rule on n x 2n cells of (theta, phi)
// (theta even, so that a narrow lobe about a pole is resolved too).
template <class Function>
double integrateOverSphere(Function g, int n) {
    double sum = 0;
    const double dTheta = std::numbers::pi / n, dPhi = std::numbers::pi / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
            const double theta = (i + 0.5) * dTheta, phi = (j + 0.5) * dPhi;
            sum += g(Vec3(static_cast<float>(std::sin(theta) * std::cos(phi)),
                          static_cast<float>(std::sin(theta) * std::sin(phi)),
                          static_cast<float>(std::cos(theta)))) *
                   std::sin(theta);
        }
    return sum * dTheta * dPhi;
}

// The pdf is a density of what sample() returns, which may return nothing (a reflection into the
// surface): it integrates to at most 1. Seen head-on, the conductor's reflection stays above the
// horizon for microfacets within 45 degrees of the normal, which the visible normals (here D(m)
// cos theta_m, with P(tan^2 theta_m < t) = t / (alpha^2 + t)) are with probability
// 1 / (1 + alpha^2): its integral. GGX's long tail loses 1% even at alpha 0.1.
TEST(RoughLobes, PdfIntegratesToAtMostOne) {
    for (const float alpha : {0.1f, 0.3f, 0.6f, 1.0f})
        for (const float theta : {0.0f, 45.0f, 80.0f, 130.0f}) {
            const Vec3 wo = direction(theta, 0);
            const RoughConductorLobe conductor(Color(1), alpha, kGold);
            const RoughDielectricLobe dielectric(Color(1), kIor, alpha);
            // 1200 bands of theta: 0.0026 radians, a tenth of the narrowest lobe (the refraction
            // at alpha 0.1, about 0.03 radians wide).
            const double conductorIntegral =
                integrateOverSphere([&](const Vec3& wi) { return conductor.pdf(wo, wi); }, 1200);
            const double dielectricIntegral =
                integrateOverSphere([&](const Vec3& wi) { return dielectric.pdf(wo, wi); }, 1200);
            EXPECT_LE(conductorIntegral, 1.002) << "alpha " << alpha << ", theta " << theta;
            EXPECT_LE(dielectricIntegral, 1.002) << "alpha " << alpha << ", theta " << theta;
            if (theta == 0) {
                EXPECT_NEAR(conductorIntegral, 1 / (1 + alpha * alpha), 0.002) << "alpha " << alpha;
            }
            if (alpha <= 0.3f && theta < 90) {
                EXPECT_GT(dielectricIntegral, 0.9) << "alpha " << alpha << ", theta " << theta;
            }
        }
}

// f(wo, wi) = f(wi, wo) for reflection; a refraction's radiance f scales by eta^2, the squared
// ratio of the indices (f(wi, wo) = eta^2 f(wo, wi), eta the index on wi's side over wo's). To
// 1e-3 relative and 1e-6 absolute: the two evaluations build the half vector from the directions
// in a different order, which float rounding tells apart at grazing angles.
TEST(RoughLobes, FIsReciprocal) {
    UniformSource random(17);
    const RoughConductorLobe conductor(Color(1), 0.4f, kGold);
    const RoughDielectricLobe dielectric(Color(1), kIor, 0.4f);
    int refractions = 0;
    for (int k = 0; k < 4000; ++k) {
        const Vec3 a = direction(179 * random.next(), 360 * random.next());
        const Vec3 b = direction(179 * random.next(), 360 * random.next());
        const float fab = conductor.f(a, b).g, fba = conductor.f(b, a).g;
        EXPECT_NEAR(fab, fba, 1e-3f * fab + 1e-6f);
        const float dab = dielectric.f(a, b).g, dba = dielectric.f(b, a).g;
        if (a.z * b.z > 0) {
            EXPECT_NEAR(dab, dba, 1e-3f * dab + 1e-6f);
            continue;
        }
        const float eta = b.z < 0 ? kIor : 1 / kIor;  // b inside the glass when b.z < 0
        EXPECT_NEAR(dba, eta * eta * dab, 1e-3f * dba + 1e-6f);
        if (dab > 0) ++refractions;
    }
    EXPECT_GT(refractions, 100);  // the refraction was exercised
}

// The directional albedo of a lobe, the integral of f |cos theta_i| over the sphere.
double albedo(const BsdfLobe& lobe, const Vec3& wo, int n) {
    return integrateOverSphere([&](const Vec3& wi) { return lobe.f(wo, wi).r * std::abs(wi.z); },
                               n);
}

// The same albedo from the lobe's own samples, f |cos| / pdf averaged: E[G1(wi)] for the rough
// mirror.
double sampledAlbedo(const BsdfLobe& lobe, const Vec3& wo, int samples, unsigned seed) {
    UniformSource random(seed);
    double sum = 0;
    for (int k = 0; k < samples; ++k) {
        const float uChoice = random.next();
        if (const auto s = lobe.sample(wo, uChoice, random.next2D()))
            sum += s->f.r * std::abs(s->wi.z) / s->pdf;
    }
    return sum / samples;
}

// A white furnace of the rough mirror with Fresnel 1: no direction reflects more than it receives.
// Single scattering loses the light that would bounce between microfacets: head-on, at least the
// visible normals beyond 45 degrees (alpha^2 / (1 + alpha^2), see above), 1.2% in all at alpha
// 0.1; more when rough and grazing. The quadrature of f cos and the
// average of the sample weights (an independent estimate: the visible normals' G1(wi)) agree.
TEST(RoughConductorLobe, WhiteFurnaceLosesOnlyTheMultipleScattering) {
    for (const float alpha : {0.1f, 0.3f, 0.6f, 1.0f})
        for (const float theta : {0.0f, 45.0f, 70.0f, 85.0f}) {
            const RoughConductorLobe mirror(Color(1), alpha, std::nullopt);
            const Vec3 wo = direction(theta, 0);
            const double quadrature = albedo(mirror, wo, 1200);
            const double sampled = sampledAlbedo(mirror, wo, 200'000, 23);
            EXPECT_LE(quadrature, 1.0 + 2e-3) << "alpha " << alpha << ", theta " << theta;
            // 200 000 samples of weights in [0, 1]: a standard error below 0.0012.
            EXPECT_NEAR(sampled, quadrature, 0.005) << "alpha " << alpha << ", theta " << theta;
            if (theta == 0) {
                EXPECT_LE(quadrature, 1 / (1 + alpha * alpha) + 1e-3) << "alpha " << alpha;
            }
            if (theta == 0 && alpha == 0.1f) {
                EXPECT_GT(quadrature, 0.985);
            }
            if (alpha == 1.0f) {
                EXPECT_LT(quadrature, 0.95) << "theta " << theta;
            }
        }
}

// Glass conserves energy: over both sides of the boundary, the flux weight (the radiance weight
// times eta^2 for a refraction) averages to at most 1.
TEST(RoughDielectricLobe, ReflectsAndRefractsNoMoreThanItReceives) {
    for (const float alpha : {0.1f, 0.3f, 0.6f, 1.0f})
        for (const float theta : {0.0f, 45.0f, 80.0f, 120.0f, 160.0f}) {
            const RoughDielectricLobe glass(Color(1), kIor, alpha);
            const Vec3 wo = direction(theta, 0);
            UniformSource random(29);
            constexpr int kSamples = 100'000;
            double flux = 0;
            for (int k = 0; k < kSamples; ++k) {
                const float uChoice = random.next();
                if (const auto s = glass.sample(wo, uChoice, random.next2D()))
                    flux += s->f.r * std::abs(s->wi.z) / s->pdf * s->etaSquared;
            }
            EXPECT_LE(flux / kSamples, 1.0 + 1e-3) << "alpha " << alpha << ", theta " << theta;
            if (alpha == 0.1f && theta == 0) {
                EXPECT_GT(flux / kSamples, 0.99);
            }
        }
}

// The exact Fresnel reflectance of a conductor, from complex arithmetic in double: the s and p
// amplitudes with cos theta_t = sqrt(1 - sin^2 theta_i / n^2), n = eta + i k.
double fresnelConductorComplex(double cosThetaI, double eta, double k) {
    const std::complex<double> n(eta, k);
    const double sin2 = 1 - cosThetaI * cosThetaI;
    const std::complex<double> cosT = std::sqrt(1.0 - sin2 / (n * n));
    const std::complex<double> rs = (cosThetaI - n * cosT) / (cosThetaI + n * cosT);
    const std::complex<double> rp = (n * cosThetaI - cosT) / (n * cosThetaI + cosT);
    return (std::norm(rs) + std::norm(rp)) / 2;
}

TEST(Optics, ConductorFresnelMeetsItsClosedForms) {
    for (const auto& [eta, k] :
         {std::pair{0.143f, 3.983f}, std::pair{1.6575f, 9.2238f}, std::pair{4.3697f, 5.2065f},
          std::pair{1.5f, 0.0f}, std::pair{0.2f, 0.5f}}) {
        const float normal = ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
        EXPECT_NEAR(fresnelConductor(1, eta, k), normal, 1e-6f) << eta << " " << k;
        EXPECT_EQ(fresnelConductor(0, eta, k), 1.0f) << eta << " " << k;
        for (const double cosTheta : {0.99, 0.8, 0.5, 0.2, 0.05, 1e-3}) {
            // Float arithmetic on terms of size eta^2 + k^2 (up to 88): 1e-5 relative.
            EXPECT_NEAR(fresnelConductor(static_cast<float>(cosTheta), eta, k),
                        fresnelConductorComplex(cosTheta, eta, k), 2e-5)
                << eta << " " << k << " at cos " << cosTheta;
        }
    }
    // A dielectric is a conductor without absorption.
    for (const float cosTheta : {1.0f, 0.7f, 0.3f})
        EXPECT_NEAR(fresnelConductor(cosTheta, kIor, 0), fresnelDielectric(cosTheta, kIor), 1e-6f);
}

// Seen head-on, each named metal reflects ((eta - 1)^2 + k^2) / ((eta + 1)^2 + k^2), the colour
// docs/SCENE-FORMAT.md's table lists (to 3 decimals).
TEST(BlinnPhongMaterial, NamedMetalsHaveTheTablesColoursAtNormalIncidence) {
    const std::vector<std::pair<std::string, Color>> expected{
        {"gold", {0.967f, 0.802f, 0.324f}},     {"silver", {0.975f, 0.958f, 0.906f}},
        {"copper", {0.952f, 0.620f, 0.511f}},   {"aluminium", {0.928f, 0.918f, 0.919f}},
        {"chromium", {0.688f, 0.649f, 0.687f}},
    };
    const auto& metals = BlinnPhongMaterial::metals();
    ASSERT_EQ(metals.size(), expected.size());
    for (std::size_t i = 0; i < metals.size(); ++i) {
        EXPECT_EQ(metals[i].name, expected[i].first);
        const Color F = fresnelConductor(1, metals[i].ior);
        EXPECT_NEAR(F.r, expected[i].second.r, 5e-4f) << expected[i].first;
        EXPECT_NEAR(F.g, expected[i].second.g, 5e-4f) << expected[i].first;
        EXPECT_NEAR(F.b, expected[i].second.b, 5e-4f) << expected[i].first;
        // The smooth conductor lobe reflects that much along the mirror direction.
        const ConductorLobe lobe(Color(1), metals[i].ior);
        const auto s = lobe.sample(Vec3(0, 0, 1), 0, {0.5f, 0.5f});
        ASSERT_TRUE(s);
        EXPECT_NEAR(s->f.g * s->wi.z / s->pdf, F.g, 1e-6f);
    }
}

// A material with roughness 0 has the smooth lobes of before: Whitted's specular rays and no
// rough ones; with roughness, the same weights in rough lobes.
BlinnPhongMaterial::Parameters mirrorAndGlass(float roughness) {
    BlinnPhongMaterial::Parameters p;
    p.diffuse = std::make_shared<ConstantTexture>(Color(0));
    p.reflection = Color(0.3f);
    p.transmission = Color(0.7f);
    p.roughness = roughness;
    return p;
}

Hit hitFacingZ() {
    Hit hit;
    hit.ng = Vec3(0, 0, 1);
    hit.ns = Vec3(0, 0, 1);
    return hit;
}

TEST(Bsdf, RoughnessZeroKeepsTheSmoothLobesAndRoughnessMakesRoughOnes) {
    const Hit hit = hitFacingZ();
    const BlinnPhongMaterial smooth(mirrorAndGlass(0)), rough(mirrorAndGlass(0.3f));
    const Bsdf smoothBsdf(smooth, hit, hit.ns, Bsdf::Weights::AsGiven);
    const Bsdf roughBsdf(rough, hit, hit.ns, Bsdf::Weights::AsGiven);
    std::array<SpecularRay, Bsdf::kMaxSpecularRays> rays;
    EXPECT_EQ(smoothBsdf.specularRays(direction(30, 0), true, rays), 2u);
    EXPECT_EQ(smoothBsdf.roughLobeCount(), 0u);
    EXPECT_FALSE(smoothBsdf.hasNonDeltaLobe());
    EXPECT_EQ(roughBsdf.specularRays(direction(30, 0), true, rays), 0u);
    EXPECT_EQ(roughBsdf.roughLobeCount(), 2u);
    EXPECT_TRUE(roughBsdf.hasNonDeltaLobe());
}

// The path tracer's Bsdf lets a rough refraction through the geometric surface (f and sample),
// and Whitted's traced rays of the glass go both ways.
TEST(Bsdf, RoughGlassRefractsThroughTheSurface) {
    const Hit hit = hitFacingZ();
    BlinnPhongMaterial::Parameters p = mirrorAndGlass(0.2f);
    p.reflection = Color(0);
    p.transmission = Color(1);
    const BlinnPhongMaterial glass(p);
    const Bsdf bsdf(glass, hit, hit.ns);
    const Vec3 wo = direction(20, 0);
    const Vec3 refracted = *refract(wo, Vec3(0, 0, 1), kIor);
    EXPECT_GT(bsdf.f(wo, normalize(refracted)).g, 0);
    EXPECT_GT(bsdf.pdf(wo, normalize(refracted)), 0);
    UniformSource random(31);
    int below = 0;
    for (int k = 0; k < 1000; ++k) {
        const float uLobe = random.next();
        if (const auto s = bsdf.sample(wo, uLobe, random.next2D())) {
            if (s->wi.z < 0) ++below;
            EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi), 1e-3f * s->pdf);
        }
    }
    // 1 - F = 0.96 of the samples refract.
    EXPECT_GT(below, 900);
    const Bsdf whitted(glass, hit, hit.ns, Bsdf::Weights::AsGiven);
    std::array<SpecularRay, 2> traced;
    ASSERT_EQ(whitted.tracedRays(0, wo, {0.3f, 0.4f}, traced), 2u);
    EXPECT_GT(traced[0].direction.z, 0);
    EXPECT_LT(traced[1].direction.z, 0);
    // F G1 + (1 - F) G1: at most 1, near 1 this smooth.
    const float total = traced[0].weight.g + traced[1].weight.g;
    EXPECT_LE(total, 1.0f);
    EXPECT_GT(total, 0.95f);
}

// Whitted's and radiosity's highlight of a rough lobe is f cos(theta_L), for delta lights only:
// an area light reaches the lobe through its traced rays instead, and would count twice.
TEST(Bsdf, RoughLobesShadeDeltaLightsOnly) {
    const Hit hit = hitFacingZ();
    BlinnPhongMaterial::Parameters p = mirrorAndGlass(0.3f);
    p.transmission = Color(0);
    p.conductor = kGold;
    const BlinnPhongMaterial gold(p);
    const Bsdf bsdf(gold, hit, hit.ns, Bsdf::Weights::AsGiven);
    const RoughConductorLobe lobe(Color(0.3f), 0.3f, kGold);
    const Vec3 wo = direction(30, 0), wi = direction(40, 180);
    const Color expected = lobe.f(wo, wi) * wi.z;
    ASSERT_GT(expected.g, 0);
    EXPECT_NEAR(bsdf.localResponse(wo, wi, true, true).g, expected.g, 1e-6f);
    EXPECT_TRUE(bsdf.localResponse(wo, wi, true, false).isBlack());
    EXPECT_NEAR(bsdf.glossyF(wo, wi, true).r, lobe.f(wo, wi).r, 1e-6f);
    EXPECT_TRUE(bsdf.glossyF(wo, wi, false).isBlack());
    EXPECT_TRUE(bsdf.hasGlossyLobe());
}

// Tiny roughness (the case that gave black dots in other renderers) and grazing directions give
// finite values and sample weights of at most the lobe's weight (glass: times eta^2, the flux of
// a refraction), never NaN.
TEST(RoughLobes, TinyRoughnessAndGrazingDirectionsStayFinite) {
    UniformSource random(37);
    for (const float alpha : {1e-4f, 1e-3f, 1.0f}) {
        const RoughConductorLobe conductor(Color(1), alpha, kGold);
        const RoughDielectricLobe dielectric(Color(1), kIor, alpha);
        for (const float theta : {0.0f, 45.0f, 89.9f, 90.1f, 135.0f, 179.9f}) {
            const Vec3 wo = direction(theta, 10);
            for (int k = 0; k < 2000; ++k) {
                const float uChoice = random.next();
                const Vec2 u = random.next2D();
                for (const BsdfLobe* lobe : {static_cast<const BsdfLobe*>(&conductor),
                                             static_cast<const BsdfLobe*>(&dielectric)}) {
                    const auto s = lobe->sample(wo, uChoice, u);
                    if (!s) continue;
                    const Color weight = s->f * (std::abs(s->wi.z) / s->pdf * s->etaSquared);
                    ASSERT_TRUE(weight.isFinite()) << "alpha " << alpha << ", theta " << theta;
                    EXPECT_LE(weight.maxComponent(), 1 + 1e-3f)
                        << "alpha " << alpha << ", theta " << theta;
                }
            }
        }
    }
}

// The GGX density D(m) integrates to 1 over the projected hemisphere (integral of D cos).
TEST(GgxDistribution, ProjectedDensityIntegratesToOne) {
    for (const float alpha : {0.1f, 0.5f, 1.0f}) {
        const GgxDistribution ggx(alpha);
        const double integral = integrateOverSphere(
            [&](const Vec3& m) { return ggx.density(m) * std::max(0.0f, m.z); }, 1500);
        EXPECT_NEAR(integral, 1, 2e-3) << "alpha " << alpha;
    }
}

}  // namespace
}  // namespace lancer::test
