// The path tracer's glass (render/materials/dielectric_bsdf.h): energy in a white furnace, Beer-Lambert
// absorption through a slab against its closed form, the rough BTDF's sampling against its own
// evaluation, and the same bits for any thread count.
#include <cmath>
#include <cstdio>

#include "accel/naive.h"
#include "render/camera_rays.h"
#include "render/materials/dielectric_bsdf.h"
#include "render/refraction.h"
#include "render/renderer.h"
#include "render/sobol_sampler.h"
#include "render_path_util.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

Material glass(float roughness, Transmission t = {.weight = 1}) {
    Material m = test::pbr({1, 1, 1}, 0, roughness);
    m.transmission = t;
    return m;
}

// A quad wound so that its front (the side light enters the volume from) faces `outward`.
void addFace(Scene& s, Vec3 a, Vec3 b, Vec3 c, Vec3 d, const Vec3& outward, std::uint32_t material) {
    if (dot(cross(b - a, c - a), outward) < 0) std::swap(b, d);
    test::addQuad(s, a, b, c, d, material);
}

// A closed box from lo to hi, faces wound outwards.
void addBox(Scene& s, const Vec3& lo, const Vec3& hi, std::uint32_t material) {
    const auto corner = [&](int i) { return Vec3{i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z}; };
    addFace(s, corner(0), corner(2), corner(6), corner(4), {-1, 0, 0}, material);
    addFace(s, corner(1), corner(3), corner(7), corner(5), {1, 0, 0}, material);
    addFace(s, corner(0), corner(1), corner(5), corner(4), {0, -1, 0}, material);
    addFace(s, corner(2), corner(3), corner(7), corner(6), {0, 1, 0}, material);
    addFace(s, corner(0), corner(1), corner(3), corner(2), {0, 0, -1}, material);
    addFace(s, corner(4), corner(5), corner(7), corner(6), {0, 0, 1}, material);
}

}  // namespace

// A glass sphere neither absorbs nor emits: in a uniform white environment it shows 1. Smooth
// glass conserves energy (each path ends outside, where the radiance scaling by eta^2 cancels):
// measured 0.9994 +- 0.0006 (24x24 pixels, 64 paths, 200 bounces). Rough glass loses what single
// scattering between microfacets does not return, most from the inside, where light meets the
// surface many times under total internal reflection: measured 0.964 at roughness 0.3, 0.588 at
// 0.7. The test holds each case to a band around these figures.
TEST(PathTracerGlass, GlassSphereInAWhiteFurnaceStaysNearOne) {
    struct Case {
        float roughness;
        double low, high;
    };
    for (const Case c : {Case{0, 0.995, 1.0}, Case{0.3f, 0.95, 0.98}, Case{0.7f, 0.55, 0.62}}) {
        Scene s = test::sphereSeenFromMinusZ(glass(c.roughness), 14);
        s.background = {1, 1, 1};
        s.flatten();
        RenderSettings settings = test::pathPicture(24, 64);
        settings.maxBounces = 200;
        const auto [mean, standardError] = test::meanOverHits(test::renderPath(s, settings));
        std::printf("glass furnace: roughness %g: %.4f +- %.4f\n", double(c.roughness), mean, standardError);
        EXPECT_GT(mean, c.low) << "roughness " << c.roughness;
        EXPECT_LT(mean, c.high + 4 * standardError) << "roughness " << c.roughness;
    }
}

// Seen straight on through a smooth slab of thickness d in front of an emitter of radiance L,
// with F the reflectance of each face and a = exp(-sigma d) (attenuationColor c reached at
// attenuationDistance D: sigma = -ln(c) / D), the light that crosses, after any number of
// reflections inside, is L (1 - F)^2 a / (1 - F^2 a^2).
TEST(PathTracerGlass, SlabTransmittanceFollowsBeerLambert) {
    for (const Real thickness : {0.5, 2.0}) {
        Scene s;
        s.background = {0, 0, 0};
        s.camera.origin = {0, 0, -10};
        s.camera.destination = {0, 0, 0};
        s.camera.fovDegrees = 1;
        Transmission t{.weight = 1, .ior = 1.5f, .attenuationColor = {0.5f, 0.25f, 0.8f}, .attenuationDistance = 1};
        addBox(s, {-5, -5, 0}, {5, 5, thickness}, test::addMaterial(s, glass(0, t)));
        Material lamp = test::pbr({0, 0, 0}, 0, 1, 0);
        lamp.emission.color = {2, 2, 2};
        addFace(s, {-50, -50, 5}, {50, -50, 5}, {50, 50, 5}, {-50, 50, 5}, {0, 0, -1}, test::addMaterial(s, lamp));
        s.flatten();
        RenderSettings settings = test::pathPicture(3, 64);
        settings.maxBounces = 50;
        const Color seen = test::renderPath(s, settings).at(1, 1);
        const double F = double(normalReflectance(1.5f));
        const auto expected = [&](float c) {
            const double a = std::exp(std::log(double(c)) * double(thickness));
            return 2 * (1 - F) * (1 - F) * a / (1 - F * F * a * a);
        };
        // a path ends at the lamp or in the black sky: no noise beyond the Fresnel choices
        EXPECT_NEAR(seen.r, expected(0.5f), 0.03 * expected(0.5f)) << "thickness " << thickness;
        EXPECT_NEAR(seen.g, expected(0.25f), 0.03 * expected(0.25f)) << "thickness " << thickness;
        EXPECT_NEAR(seen.b, expected(0.8f), 0.03 * expected(0.8f)) << "thickness " << thickness;
    }
}

// The rough BTDF's importance sampling against a uniform-sphere estimate of the same integral:
// two estimators that share only evaluate(), entering and leaving the glass, and a thin sheet.
TEST(PathTracerGlass, RoughDielectricSamplingAgreesWithUniformSampling) {
    for (const int side : {0, 1, 2})
        for (const float roughness : {0.3f, 0.7f}) {
            const bool entering = side != 1;
            const DielectricBsdf bsdf({.weight = 1, .ior = 1.5f, .thin = side == 2}, roughness, entering);
            const Vec3 wo{Real(0.6), 0, Real(0.8)};
            constexpr int kSamples = 1 << 17;
            double byImportance = 0, byUniform = 0;
            for (int i = 0; i < kSamples; ++i) {
                SobolSampler a(7, 9, std::uint32_t(i), 1), b(7, 9, std::uint32_t(i), 2);
                const Real lobe = a.next1D();
                const auto [u1, u2] = a.next2D();
                if (const auto s = bsdf.sample(wo, lobe, u1, u2)) {
                    byImportance += s->weight.g;
                    EXPECT_NEAR(s->pdf, bsdf.pdf(wo, s->wi), 1e-3 * s->pdf);
                }
                const auto [v1, v2] = b.next2D();
                const Real z = 1 - 2 * v1, r = std::sqrt(std::max(Real(0), 1 - z * z));
                const Vec3 wi{r * std::cos(2 * kPi * v2), r * std::sin(2 * kPi * v2), z};
                byUniform += bsdf.evaluate(wo, wi).g * 4 * kPi;  // pdf 1 / (4 pi)
            }
            byImportance /= kSamples, byUniform /= kSamples;
            std::printf("rough dielectric, side %d, roughness %g: %.4f by sampling, %.4f uniform\n", side,
                        double(roughness), byImportance, byUniform);
            EXPECT_NEAR(byImportance, byUniform, 0.02 * byUniform) << "side " << side << ", " << roughness;
        }
}

TEST(PathTracerGlass, SameBitsForAnyThreadCount) {
    Scene s = test::spheresOnFloor();
    s.materials[2] = glass(0);
    s.materials[3] = glass(0.4f, {.weight = 0.8f, .attenuationColor = {0.9f, 0.5f, 0.5f}, .attenuationDistance = 1});
    s.flatten();
    RenderSettings one = test::pathPicture(32, 4);
    one.threads = 1;
    RenderSettings two = one;
    two.threads = 2;
    EXPECT_EQ(test::renderPath(s, one).pixels(), test::renderPath(s, two).pixels());
}

// KHR_materials_transmission's transmissionTexture: a smooth black sheet of glass of ior 1 (light goes
// straight through, nothing is reflected) with transmission 0.5 times a checker's red channel, in
// front of a white sky. Where the checker is 1 both integrators show half the sky, where it is 0
// nothing: the pixels measured, away from the cells' edges.
TEST(PathTracerGlass, TransmissionTextureScalesTheTransmissionPerHit) {
    Scene s;
    s.background = {1, 1, 1};
    s.camera.fovDegrees = 20;  // the sheet at z = 5.5 shows about two cells across
    s.textures.push_back({.name = "checker", .kind = Texture::Kind::Checker, .colorA = {1, 0, 0}, .colorB = {0, 1, 1}});
    Material sheet = test::pbr({0, 0, 0}, 0, 0, 0);
    sheet.transmission = {.weight = 0.5f, .ior = 1, .thin = true};
    sheet.transmission.texture = 0;
    const auto m = test::addMaterial(s, sheet);
    test::addQuad(s, {-100, -100, 5.5}, {100, -100, 5.5}, {100, 100, 5.5}, {-100, 100, 5.5}, m);
    s.flatten();
    const int size = 16;
    const CameraRays camera(s.camera, size, size);
    // the checker's red where the ray through (x, y) meets the sheet; -1 near a cell's edge
    const auto checkerRed = [&](Real x, Real y) {
        const Vec3 d = camera.at(x, y).direction;
        const Vec3 p = d * (Real(5.5) / d.z);
        if (std::abs(p.x - std::round(p.x)) < 0.1 || std::abs(p.y - std::round(p.y)) < 0.1) return -1;
        return (int(std::floor(p.x)) + int(std::floor(p.y)) + 5) % 2 == 0 ? 1 : 0;
    };
    for (const Integrator integrator : {Integrator::Whitted, Integrator::Path}) {
        RenderSettings settings = test::pathPicture(size, 64);
        settings.integrator = integrator;
        settings.pixelSamples = integrator == Integrator::Path ? 64 : 1;
        const Framebuffer image = test::renderPath(s, settings);
        int clear = 0, opaque = 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const int red = checkerRed(x, y);  // the pixel's corner and its far corner agree
                if (red < 0 || red != checkerRed(x + 1, y + 1)) continue;
                const float want = 0.5f * float(red);
                EXPECT_NEAR(image.at(x, y).g, want, 0.02)
                    << x << "," << y << (red ? " clear" : " opaque") << " path " << (integrator == Integrator::Path);
                (red ? clear : opaque) += 1;
            }
        EXPECT_GT(clear, 10);
        EXPECT_GT(opaque, 10);
    }
}
