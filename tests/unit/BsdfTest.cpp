// The path tracer's BSDF, lobe by lobe and as a whole: the directions each lobe samples follow the
// density its pdf() states (a chi-square test over a (theta, phi) grid, as in pbrt-v3's bsdfs test
// and Mitsuba's chi2 module), the Blinn-Phong lobe never reflects more than it receives (a white
// furnace, numerically integrated), reflection is reciprocal, and glass conserves energy; and
// Whitted's local model and specular rays, from the same lobes.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "DirectionChiSquare.h"
#include "geometry/Hit.h"
#include "materials/BlinnPhongLobe.h"
#include "materials/BlinnPhongMaterial.h"
#include "materials/Bsdf.h"
#include "materials/ConstantTexture.h"
#include "materials/DielectricLobe.h"
#include "materials/LambertianLobe.h"
#include "materials/MirrorLobe.h"
#include "materials/Optics.h"
#include "math/Float.h"

namespace lancer::test {
namespace {

// One test in many may fail by chance with probability alpha; Bonferroni's correction keeps the
// whole suite's false-alarm rate at 1%.
constexpr double kSuiteSignificance = 0.01;
constexpr int kChiSquareTests = 40;
constexpr int kChiSquareSamples = 1'000'000;

void expectChiSquarePasses(const DirectionSampler& sampler, unsigned seed) {
    std::string problem;
    const double p = chiSquarePValue(sampler, kChiSquareSamples, seed, problem);
    EXPECT_TRUE(problem.empty()) << problem;
    EXPECT_GT(p, kSuiteSignificance / kChiSquareTests)
        << "the sampled directions do not follow pdf()";
}

DirectionSampler lobeSampler(const BsdfLobe& lobe, const Vec3& wo) {
    return {[&lobe, wo](UniformSource& random) -> std::optional<Vec3> {
                const auto s = lobe.sample(wo, 0, random.next2D());
                if (!s) return std::nullopt;
                return s->wi;
            },
            [&lobe, wo](const Vec3& wi) { return static_cast<double>(lobe.pdf(wo, wi)); }};
}

struct LobeCase {
    std::string name;
    float exponent;  // < 0: the Lambertian lobe
    float woTheta;   // degrees from the normal; > 90 comes from the back side
};

class LobeSampling : public testing::TestWithParam<LobeCase> {};

TEST_P(LobeSampling, DirectionsFollowThePdf) {
    const LobeCase& c = GetParam();
    const LambertianLobe lambertian(Color(0.5f));
    const BlinnPhongLobe blinnPhong(Color(0.5f), std::max(0.0f, c.exponent));
    const BsdfLobe& lobe = c.exponent < 0 ? static_cast<const BsdfLobe&>(lambertian) : blinnPhong;
    expectChiSquarePasses(lobeSampler(lobe, direction(c.woTheta, 30)),
                          static_cast<unsigned>(c.woTheta * 100 + c.exponent));
}

INSTANTIATE_TEST_SUITE_P(
    Lobes, LobeSampling,
    testing::Values(
        LobeCase{"LambertNormal", -1, 0}, LobeCase{"LambertOblique", -1, 60},
        LobeCase{"LambertBackSide", -1, 130}, LobeCase{"BlinnPhong0Oblique", 0, 50},
        LobeCase{"BlinnPhong1Normal", 1, 0}, LobeCase{"BlinnPhong1Grazing", 1, 80},
        LobeCase{"BlinnPhong10Normal", 10, 0}, LobeCase{"BlinnPhong10Oblique", 10, 45},
        LobeCase{"BlinnPhong10Grazing", 10, 85}, LobeCase{"BlinnPhong10BackSide", 10, 140},
        LobeCase{"BlinnPhong50Oblique", 50, 30}, LobeCase{"BlinnPhong50Grazing", 50, 75},
        LobeCase{"BlinnPhong300Normal", 300, 0}, LobeCase{"BlinnPhong300Oblique", 300, 60}),
    [](const testing::TestParamInfo<LobeCase>& test) { return test.param.name; });

// A material made of the given weights, seen at a hit whose normals are +z (or the shading normal
// tilted away from the geometric one by `tiltDegrees`).
// The Bsdfs of these materials are given the shading normal as the viewer's direction: only a
// normal or bump map, which these have none of, reads it.
struct MaterialAtHit {
    BlinnPhongMaterial material;
    Hit hit;

    MaterialAtHit(float kd, float ks, float shininess, float kr, float kt, float tiltDegrees = 0)
        : material(weights(kd, ks, shininess, kr, kt)) {
        hit.ng = Vec3(0, 0, 1);
        hit.ns = direction(tiltDegrees, 0);
    }

    static BlinnPhongMaterial::Parameters weights(float kd, float ks, float shininess, float kr,
                                                  float kt) {
        BlinnPhongMaterial::Parameters p;
        p.diffuse = std::make_shared<ConstantTexture>(Color(kd));
        p.specular = Color(ks);
        p.shininess = shininess;
        p.reflection = Color(kr);
        p.transmission = Color(kt);
        return p;
    }
};

TEST(Bsdf, MixtureOfDiffuseAndHighlightFollowsItsPdf) {
    const MaterialAtHit m(0.3f, 0.5f, 40, 0, 0);
    const Bsdf bsdf(m.material, m.hit, m.hit.ns);
    for (const float theta : {0.0f, 50.0f, 120.0f}) {
        const Vec3 wo = direction(theta, 70);
        expectChiSquarePasses(
            {[&](UniformSource& random) -> std::optional<Vec3> {
                 const float uLobe = random.next();
                 const auto s = bsdf.sample(wo, uLobe, random.next2D());
                 if (!s) return std::nullopt;
                 return s->wi;
             },
             [&](const Vec3& wi) { return static_cast<double>(bsdf.pdf(wo, wi)); }},
            static_cast<unsigned>(theta + 7));
    }
}

// The path tracer draws uLobe only where sample() reads it: where it says it does not, every
// uLobe gives the same sample, to the bit; where it says it does, some sample changes with it.
TEST(Bsdf, ReadsTheLobeChoiceExactlyWhereTheSampleDependsOnIt) {
    struct Case {
        std::string name;
        BlinnPhongMaterial::Parameters parameters;
        bool reads;
    };
    BlinnPhongMaterial::Parameters roughGlass = MaterialAtHit::weights(0, 0, 1, 0, 0.9f);
    roughGlass.roughness = 0.3f;
    BlinnPhongMaterial::Parameters roughMetalAndGlass = roughGlass;
    roughMetalAndGlass.reflection = Color(0.5f);
    const std::vector<Case> cases = {
        {"diffuse", MaterialAtHit::weights(0.6f, 0, 1, 0, 0), false},
        {"highlight", MaterialAtHit::weights(0, 0.5f, 40, 0, 0), false},
        {"mirror", MaterialAtHit::weights(0, 0, 1, 0.9f, 0), false},
        {"glass (Fresnel chosen by u)", MaterialAtHit::weights(0, 0, 1, 0, 0.9f), false},
        {"diffuse and highlight", MaterialAtHit::weights(0.3f, 0.5f, 40, 0, 0), true},
        {"diffuse and mirror", MaterialAtHit::weights(0.3f, 0, 1, 0.5f, 0), true},
        {"rough glass (Fresnel chosen by uLobe)", roughGlass, true},
        {"rough metal and glass", roughMetalAndGlass, true},
    };
    const auto same = [](const std::optional<BsdfSample>& a, const std::optional<BsdfSample>& b) {
        if (a.has_value() != b.has_value()) return false;
        return !a || (a->wi == b->wi && a->f == b->f && a->pdf == b->pdf &&
                      a->isDelta == b->isDelta && a->etaSquared == b->etaSquared);
    };
    for (const Case& c : cases) {
        Hit hit;
        hit.ng = Vec3(0, 0, 1);
        hit.ns = hit.ng;
        const BlinnPhongMaterial material(c.parameters);
        const Bsdf bsdf(material, hit, hit.ns);
        EXPECT_EQ(bsdf.readsLobeChoice(), c.reads) << c.name;
        UniformSource random(11);
        bool changed = false;
        for (int k = 0; k < 400; ++k) {
            const Vec3 wo = direction(static_cast<float>(170 * random.next()),
                                      static_cast<float>(360 * random.next()));
            const Vec2 u = random.next2D();
            const std::optional<BsdfSample> first = bsdf.sample(wo, 0, u);
            for (const float uLobe : {0.2f, 0.5f, 0.8f, kOneMinusEpsilon}) {
                const bool equal = same(first, bsdf.sample(wo, uLobe, u));
                if (!c.reads) {
                    ASSERT_TRUE(equal) << c.name << ": uLobe " << uLobe << " changed the sample";
                }
                changed = changed || !equal;
            }
        }
        EXPECT_EQ(changed, c.reads) << c.name;
    }
}

// For a mixture and for a lobe alone (whose sample's f and pdf the Bsdf takes as the lobe gives
// them), from the front and from the back.
TEST(Bsdf, SampledValuesAreThoseOfFAndPdf) {
    for (const auto& [kd, ks] :
         {std::pair{0.3f, 0.5f}, std::pair{0.6f, 0.0f}, std::pair{0.0f, 0.5f}})
        for (const float woTheta : {35.0f, 130.0f}) {
            const MaterialAtHit m(kd, ks, 40, 0, 0);
            const Bsdf bsdf(m.material, m.hit, m.hit.ns);
            UniformSource random(3);
            const Vec3 wo = direction(woTheta, 10);
            int sampled = 0;
            for (int k = 0; k < 1000; ++k) {
                const float uLobe = random.next();
                const auto s = bsdf.sample(wo, uLobe, random.next2D());
                if (!s) continue;
                ++sampled;
                EXPECT_FALSE(s->isDelta);
                EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi), 1e-4f * s->pdf);
                EXPECT_NEAR(s->f.r, bsdf.f(wo, s->wi).r, 1e-4f * s->f.r);
            }
            EXPECT_GT(sampled, 500) << "kd " << kd << ", ks " << ks << ", wo at " << woTheta;
        }
}

// The directional albedo: the integral of f cos(theta_i) over the sphere of incident directions,
// by the midpoint rule on a (cos theta, phi) grid fine enough for the narrowest lobe tested.
double albedoByQuadrature(const BsdfLobe& lobe, const Vec3& wo, int cells) {
    double sum = 0;
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < 2 * cells; ++j) {
            const double cosTheta = (i + 0.5) / cells;
            const double sinTheta = std::sqrt(1 - cosTheta * cosTheta);
            const double phi = (j + 0.5) / (2 * cells) * 2 * std::numbers::pi;
            const Vec3 wi(static_cast<float>(sinTheta * std::cos(phi)),
                          static_cast<float>(sinTheta * std::sin(phi)),
                          static_cast<float>(cosTheta));
            sum += lobe.f(wo, wi).r * cosTheta;
        }
    // Each cell spans d(cos theta) d(phi) = (1 / cells) (pi / cells) of solid angle.
    return sum * std::numbers::pi / (static_cast<double>(cells) * cells);
}

// A white furnace for the highlight: with ks = 1, no direction reflects more than it receives,
// whatever the exponent, and a narrow lobe seen head-on reflects nearly all of it (the
// normalization is not so stingy that it is simply dark).
TEST(BlinnPhongLobe, AlbedoNeverExceedsOne) {
    for (const float exponent : {0.0f, 1.0f, 8.0f, 32.0f, 128.0f, 512.0f, 2048.0f}) {
        const BlinnPhongLobe lobe(Color(1), exponent);
        for (const float theta : {0.0f, 20.0f, 45.0f, 70.0f, 85.0f, 89.0f}) {
            const Vec3 wo = direction(theta, 0);
            // The lobe's width shrinks as 1 / sqrt(exponent): the grid follows.
            const int cells = 200 + static_cast<int>(30 * std::sqrt(exponent));
            const double albedo = albedoByQuadrature(lobe, wo, cells);
            EXPECT_LE(albedo, 1.0 + 2e-3) << "exponent " << exponent << ", theta " << theta;
            // Measured: 0.886 for exponent 32, 0.969 for 128, 0.991 for 512 (broad lobes lose
            // what they would send below the horizon, and to the max() term).
            if (theta == 0 && exponent >= 128) {
                EXPECT_GT(albedo, 0.95) << "exponent " << exponent;
            }
        }
    }
}

// The same albedo from the lobe's own samples: f cos / pdf averaged. It must agree with the
// quadrature (the sampler and f are consistent) and never exceed ks in any single sample.
TEST(BlinnPhongLobe, SampleWeightsNeverExceedKsAndAverageToTheAlbedo) {
    for (const float exponent : {1.0f, 32.0f, 512.0f}) {
        const BlinnPhongLobe lobe(Color(0.9f), exponent);
        const Vec3 wo = direction(40, 0);
        UniformSource random(11);
        constexpr int kSamples = 400'000;
        double sum = 0;
        for (int k = 0; k < kSamples; ++k) {
            const auto s = lobe.sample(wo, 0, random.next2D());
            if (!s) continue;
            const double weight = s->f.r * std::abs(s->wi.z) / s->pdf;
            ASSERT_LE(weight, 0.9 * (1 + 1e-5));
            sum += weight;
        }
        const double quadrature =
            albedoByQuadrature(lobe, wo, 400 + static_cast<int>(60 * std::sqrt(exponent)));
        EXPECT_NEAR(sum / kSamples, quadrature, 0.01 * quadrature) << "exponent " << exponent;
    }
}

TEST(Bsdf, ReflectionIsReciprocal) {
    const MaterialAtHit m(0.4f, 0.5f, 25, 0, 0);
    const Bsdf bsdf(m.material, m.hit, m.hit.ns);
    const LambertianLobe lambertian(Color(0.7f));
    const BlinnPhongLobe blinnPhong(Color(0.7f), 60);
    UniformSource random(5);
    for (int k = 0; k < 2000; ++k) {
        const Vec3 a = direction(89 * random.next(), 360 * random.next());
        const Vec3 b = direction(89 * random.next(), 360 * random.next());
        for (const BsdfLobe* lobe : {static_cast<const BsdfLobe*>(&lambertian),
                                     static_cast<const BsdfLobe*>(&blinnPhong)}) {
            const float fab = lobe->f(a, b).r, fba = lobe->f(b, a).r;
            EXPECT_NEAR(fab, fba, 1e-4f * std::max(fab, 1e-3f));
        }
        EXPECT_NEAR(bsdf.f(a, b).g, bsdf.f(b, a).g, 1e-4f * std::max(bsdf.f(a, b).g, 1e-3f));
    }
}

// Weights above 1 in total are scaled down together: a white furnace on the whole BSDF.
TEST(Bsdf, CombinedWeightsAboveOneAreScaledToConserveEnergy) {
    const MaterialAtHit m(0.9f, 0.6f, 20, 0.5f, 0, 0);
    const Bsdf bsdf(m.material, m.hit, m.hit.ns);
    UniformSource random(9);
    constexpr int kSamples = 200'000;
    for (const float theta : {0.0f, 45.0f, 80.0f}) {
        const Vec3 wo = direction(theta, 15);
        double sum = 0;
        for (int k = 0; k < kSamples; ++k) {
            const float uLobe = random.next();
            const auto s = bsdf.sample(wo, uLobe, random.next2D());
            if (s) sum += s->f.r * std::abs(s->wi.z) / s->pdf;
        }
        EXPECT_LE(sum / kSamples, 1.0 + 0.01) << "theta " << theta;
        // (0.9 + 0.6 + 0.5) / 2: the diffuse and mirror shares alone reflect (0.9 + 0.5) / 2.
        EXPECT_GT(sum / kSamples, 0.69) << "theta " << theta;
    }
}

TEST(MirrorLobe, ReflectsAboutTheNormalWithWeightKr) {
    const MirrorLobe mirror(Color(0.25f, 0.5f, 0.75f));
    const Vec3 wo = direction(30, 40);
    const auto s = mirror.sample(wo, 0, {0.3f, 0.6f});
    ASSERT_TRUE(s);
    EXPECT_TRUE(s->isDelta);
    EXPECT_NEAR(s->wi.x, -wo.x, 1e-6f);
    EXPECT_NEAR(s->wi.y, -wo.y, 1e-6f);
    EXPECT_NEAR(s->wi.z, wo.z, 1e-6f);
    const Color weight = s->f * std::abs(s->wi.z) / s->pdf;
    EXPECT_NEAR(weight.r, 0.25f, 1e-6f);
    EXPECT_NEAR(weight.b, 0.75f, 1e-6f);
}

// A smooth dielectric reflects the Fresnel fraction and refracts the rest: over the choice of
// u, the expected flux weight (the radiance weight times eta^2 for a refraction) is kt, for
// light from outside and from inside, total internal reflection included.
TEST(DielectricLobe, ConservesEnergyAndSplitsByFresnel) {
    const float ior = 1.5f;
    const DielectricLobe glass(Color(1), ior);
    for (const float theta : {0.0f, 30.0f, 60.0f, 85.0f, 150.0f, 135.0f, 120.0f}) {
        const Vec3 wo = direction(theta, 20);
        const float eta = wo.z > 0 ? ior : 1 / ior;
        const float F = fresnelDielectric(std::abs(wo.z), eta);
        constexpr int kSteps = 10000;
        double flux = 0, reflected = 0;
        for (int k = 0; k < kSteps; ++k) {
            const auto s = glass.sample(wo, 0, {(static_cast<float>(k) + 0.5f) / kSteps, 0.5f});
            ASSERT_TRUE(s);
            const bool transmitted = s->wi.z * wo.z < 0;
            flux += s->f.r * std::abs(s->wi.z) / s->pdf * s->etaSquared;
            if (!transmitted) {
                reflected += 1;
                EXPECT_NEAR(s->wi.z, wo.z, 1e-6f);
            } else {
                // Snell's law: sin(theta_t) = sin(theta_i) / eta.
                const float sinI = std::sqrt(1 - wo.z * wo.z),
                            sinT = std::sqrt(1 - s->wi.z * s->wi.z);
                EXPECT_NEAR(sinT, sinI / eta, 1e-5f);
            }
        }
        EXPECT_NEAR(flux / kSteps, 1.0, 1e-5) << "theta " << theta;
        EXPECT_NEAR(reflected / kSteps, F, 2.0 / kSteps) << "theta " << theta;
    }
    // Beyond the critical angle (41.8 degrees inside glass of 1.5), everything is reflected.
    EXPECT_EQ(fresnelDielectric(std::abs(direction(135, 0).z), 1 / ior), 1.0f);
}

// A smooth-shading normal must not let a reflection lobe send light through the true surface.
TEST(Bsdf, NoReflectionThroughTheGeometricSurface) {
    const MaterialAtHit m(0.8f, 0, 32, 0, 0, 30);
    const Bsdf bsdf(m.material, m.hit, m.hit.ns);
    // Above the shading horizon, below the geometric one.
    const Vec3 wo = direction(45, 0);
    const Vec3 wi = direction(100, 0);
    ASSERT_GT(dot(wi, m.hit.ns), 0);
    EXPECT_TRUE(bsdf.f(wo, wi).isBlack());
    UniformSource random(2);
    for (int k = 0; k < 10000; ++k) {
        const float uLobe = random.next();
        if (const auto s = bsdf.sample(wo, uLobe, random.next2D())) {
            EXPECT_GT(s->wi.z, 0);
        }
    }
}

// Whitted's local model, from the lobes with their weights as given (kd + ks above 1 is not
// scaled): kd max(0, n.L) + ks max(0, n.h)^n, nothing for light behind the viewer's side.
TEST(Bsdf, LocalResponseIsTheSceneFormatsEquation) {
    const MaterialAtHit m(0.7f, 0.6f, 20, 0.3f, 0);
    const Bsdf bsdf(m.material, m.hit, m.hit.ns, Bsdf::Weights::AsGiven);
    const Vec3 wo = direction(30, 0), wi = direction(50, 160);
    const float cosL = wi.z, cosH = normalize(wo + wi).z;
    const Color expected = Color(0.7f) * cosL + Color(0.6f) * std::pow(cosH, 20.0f);
    EXPECT_NEAR(bsdf.localResponse(wo, wi, true, true).g, expected.g, 1e-6f);
    EXPECT_TRUE(bsdf.localResponse(wo, direction(100, 0), true, true).isBlack());
    // Seen from the back side, the model is mirrored.
    const auto mirrored = [](const Vec3& v) { return Vec3(v.x, v.y, -v.z); };
    EXPECT_NEAR(bsdf.localResponse(mirrored(wo), mirrored(wi), false, true).g, expected.g, 1e-6f);
    EXPECT_NEAR(bsdf.diffuseReflectance().r, 0.7f, 0);
    EXPECT_TRUE(bsdf.hasGlossyLobe());
}

// A mirror and glass: one reflected ray of kr + kt F, one refracted ray of kt (1 - F) along
// Snell's direction; under total internal reflection, the reflection alone with kr + kt.
TEST(Bsdf, SpecularRaysMergeTheReflectionsAndSplitGlassByFresnel) {
    const MaterialAtHit m(0, 0, 20, 0.25f, 0.5f);
    const Bsdf bsdf(m.material, m.hit, m.hit.ns, Bsdf::Weights::AsGiven);
    EXPECT_FALSE(bsdf.hasGlossyLobe());
    std::array<SpecularRay, Bsdf::kMaxSpecularRays> rays;
    const Vec3 wo = direction(40, 10);
    const float F = fresnelDielectric(wo.z, 1.5f);
    ASSERT_EQ(bsdf.specularRays(wo, true, rays), 2u);
    EXPECT_NEAR(rays[0].direction.z, wo.z, 1e-6f);
    EXPECT_NEAR(rays[0].direction.x, -wo.x, 1e-6f);
    EXPECT_NEAR(rays[0].weight.r, 0.25f + 0.5f * F, 1e-6f);
    EXPECT_NEAR(rays[1].weight.r, 0.5f * (1 - F), 1e-6f);
    EXPECT_LT(rays[1].direction.z, 0);
    EXPECT_NEAR(std::sqrt(1 - rays[1].direction.z * rays[1].direction.z),
                std::sqrt(1 - wo.z * wo.z) / 1.5f, 1e-5f);
    // From inside the glass, beyond the critical angle.
    const Vec3 inside = direction(135, 0);
    ASSERT_EQ(bsdf.specularRays(inside, false, rays), 1u);
    EXPECT_NEAR(rays[0].direction.z, inside.z, 1e-6f);
    EXPECT_NEAR(rays[0].weight.r, 0.75f, 1e-6f);
}

// Glass alone, with no mirror: the reflection is its Fresnel share, ahead of the refraction.
TEST(Bsdf, SpecularRaysOfGlassAloneStartWithItsReflection) {
    const MaterialAtHit m(0.5f, 0, 20, 0, 1);
    const Bsdf bsdf(m.material, m.hit, m.hit.ns, Bsdf::Weights::AsGiven);
    std::array<SpecularRay, Bsdf::kMaxSpecularRays> rays;
    const Vec3 wo = direction(0, 0);
    ASSERT_EQ(bsdf.specularRays(wo, true, rays), 2u);
    EXPECT_NEAR(rays[0].weight.r, fresnelDielectric(1, 1.5f), 1e-6f);
    EXPECT_NEAR(rays[1].direction.z, -1, 1e-6f);
    // A diffuse material alone traces nothing.
    const MaterialAtHit matte(0.5f, 0, 20, 0, 0);
    EXPECT_EQ(Bsdf(matte.material, matte.hit, matte.hit.ns, Bsdf::Weights::AsGiven)
                  .specularRays(wo, true, rays),
              0u);
}

}  // namespace
}  // namespace lancer::test
