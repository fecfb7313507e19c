// The clear coat (render/materials/clearcoat_bsdf.h, KHR_materials_clearcoat): its peak at normal
// incidence is the Fresnel reflectance of ior 1.5, a white coat over a white base makes no light,
// its sampling agrees with its evaluation, and bsdfAt gives it to the materials that have one.
#include <cmath>

#include "render/materials/bsdf.h"
#include "render/materials/clearcoat_bsdf.h"
#include "render/materials/microfacet.h"
#include "render/sobol_sampler.h"
#include "render_path_util.h"
#include "test_util.h"

using namespace rt;

namespace {

constexpr int kSamples = 1 << 16;

Vec3 directionAt(double cosTheta) { return {Real(std::sqrt(1 - cosTheta * cosTheta)), 0, Real(cosTheta)}; }

// The BSDF's directional albedo at wo, by its own importance sampling (green channel).
template <class Bsdf>
double albedoBySampling(const Bsdf& bsdf, const Vec3& wo) {
    double sum = 0;
    for (int i = 0; i < kSamples; ++i) {
        SobolSampler a(3, 5, std::uint32_t(i), 1);
        const Real lobe = a.next1D();
        const auto [u1, u2] = a.next2D();
        if (const auto s = bsdf.sample(wo, lobe, u1, u2)) sum += s->weight.g;
    }
    return sum / kSamples;
}

// The same by uniform sampling of the hemisphere: an estimator that shares only evaluate().
template <class Bsdf>
double albedoByUniformSampling(const Bsdf& bsdf, const Vec3& wo) {
    double sum = 0;
    for (int i = 0; i < kSamples; ++i) {
        SobolSampler b(3, 5, std::uint32_t(i), 2);
        const auto [v1, v2] = b.next2D();
        const Real z = v1, r = std::sqrt(std::max(Real(0), 1 - z * z));
        sum += bsdf.evaluate(wo, {r * std::cos(2 * kPi * v2), r * std::sin(2 * kPi * v2), z}).g * 2 * kPi;
    }
    return sum / kSamples;
}

const PbrBsdf kBlack({0, 0, 0}, {.metallic = 0, .roughness = 1, .specular = 0});
const PbrBsdf kWhiteLambertian({1, 1, 1}, {.metallic = 0, .roughness = 1, .specular = 0});

}  // namespace

// A smooth coat over a black base, seen head-on, reflects what a smooth dielectric of ior 1.5
// does: F0 = ((1.5 - 1) / (1.5 + 1))^2 = 0.04, times the coat's weight.
TEST(Clearcoat, PeakAtNormalIncidenceIsTheF0OfIor1_5) {
    EXPECT_NEAR(albedoBySampling(ClearcoatBsdf(kBlack, 1, 0), {0, 0, 1}), 0.04, 5e-4);
    EXPECT_NEAR(albedoBySampling(ClearcoatBsdf(kBlack, 0.5f, 0), {0, 0, 1}), 0.02, 3e-4);
    // at grazing angles Fresnel's law reflects more
    EXPECT_GT(albedoBySampling(ClearcoatBsdf(kBlack, 1, 0), directionAt(0.2)), 0.2);
}

// White coat over a white Lambertian base (albedo 1): what the coat reflects it takes from the
// base, so the sum stays at most 1 at every angle and roughness (a rough coat loses a little to
// masking, as single-scattering GGX does).
TEST(Clearcoat, WhiteCoatOverWhiteBaseMakesNoEnergy) {
    for (const float roughness : {0.0f, 0.3f, 0.6f, 1.0f})
        for (const double cosTheta : {1.0, 0.7, 0.4, 0.1}) {
            const ClearcoatBsdf coated(kWhiteLambertian, 1, roughness);
            const double albedo = albedoBySampling(coated, directionAt(cosTheta));
            EXPECT_LE(albedo, 1.002) << "roughness " << roughness << ", cos " << cosTheta;
            EXPECT_GT(albedo, 0.85) << "roughness " << roughness << ", cos " << cosTheta;
        }
}

// sample() and pdf() are the density of one strategy and evaluate() its integrand: the albedo by
// importance sampling agrees with plain uniform sampling of the hemisphere.
TEST(Clearcoat, ImportanceSamplingAgreesWithUniformSampling) {
    const PbrBsdf redMetal({0.9f, 0.2f, 0.1f}, {.metallic = 1, .roughness = 0.5f, .specular = 1});
    for (const float roughness : {0.3f, 0.6f, 1.0f})
        for (const double cosTheta : {0.9, 0.5, 0.2}) {
            const ClearcoatBsdf coated(redMetal, 0.8f, roughness);
            const Vec3 wo = directionAt(cosTheta);
            const double byUniform = albedoByUniformSampling(coated, wo);
            EXPECT_NEAR(albedoBySampling(coated, wo), byUniform, 0.01 * byUniform)
                << "roughness " << roughness << ", cos " << cosTheta;
        }
}

// The factory gives a coated material its coat: a smooth coat over black shows in the mirror
// direction, where the bare black base reflects nothing.
TEST(Clearcoat, BsdfAtCoatsTheMaterialsThatHaveOne) {
    Scene scene;
    Material m = test::pbr({0, 0, 0}, 0, 1, 0);
    SurfacePoint s{};
    const Vec3 wo = directionAt(0.8), mirrored{-wo.x, -wo.y, wo.z};
    Real lobe = 0.5;
    EXPECT_EQ(bsdfAt({scene}, m, s, lobe).evaluate(wo, mirrored), Color{});
    m.clearcoat = {.weight = 1, .roughness = 0.1f};
    const Bsdf coated = bsdfAt({scene}, m, s, lobe);
    EXPECT_GT(coated.evaluate(wo, mirrored).g, 0.1f);
    EXPECT_TRUE(isNonSpecular(coated.flags()));
}

// A coated white sphere in a white furnace, through the whole path tracer: no light is made.
TEST(Clearcoat, CoatedWhiteSphereInAWhiteFurnaceStaysAtMostOne) {
    Material m = test::pbr({1, 1, 1}, 0, 1, 0);
    m.clearcoat = {.weight = 1, .roughness = 0.2f};
    Scene s = test::sphereSeenFromMinusZ(m, 14);
    s.background = {1, 1, 1};
    s.flatten();
    RenderSettings settings = test::pathPicture(24, 64);
    settings.maxBounces = 200;
    const test::ImageMean mean = test::meanOverHits(test::renderPath(s, settings));
    EXPECT_LT(mean.mean, 1 + 4 * mean.standardError + 1e-3);
    EXPECT_GT(mean.mean, 0.95);
}
