// The path tracer's sky (render/lights/environment_light.h): the equirectangular mapping, an image of
// one colour lighting as the same background colour does, and importance sampling of a small
// bright spot: the same mean as uniform sampling, with far less variance.
#include <cmath>
#include <cstdio>
#include <type_traits>

#include "render/lights/environment_light.h"
#include "render/lights/light_distribution.h"
#include "render/sampling.h"
#include "render/sobol_sampler.h"
#include "render_path_util.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

Scene withEnvironmentTexture(Scene s) {
    s.textures.push_back({.name = "environment", .file = "sky.exr"});
    s.environment = Environment{.texture = std::uint32_t(s.textures.size() - 1)};
    return s;
}

}  // namespace

TEST(EnvironmentLight, EquirectangularMappingHasYUpAndTheCentreAlongMinusZ) {
    const auto near = [](const Vec3& a, const Vec3& b) { return length(a - b) < 1e-5; };
    EXPECT_TRUE(near(equirectangularDirection(0.5, 0), {0, 1, 0}));
    EXPECT_TRUE(near(equirectangularDirection(0.5, 1), {0, -1, 0}));
    EXPECT_TRUE(near(equirectangularDirection(0.5, 0.5), {0, 0, -1}));
    EXPECT_TRUE(near(equirectangularDirection(0.75, 0.5), {1, 0, 0}));
    for (const Real s : {0.1, 0.4, 0.9})
        for (const Real t : {0.2, 0.5, 0.7}) {
            const auto [s2, t2] = equirectangularCoordinates(equirectangularDirection(s, t));
            EXPECT_NEAR(s2, s, 1e-5);
            EXPECT_NEAR(t2, t, 1e-5);
        }
}

// A white Lambertian sphere lit by an image of one colour c shows c, as under a background of c.
TEST(EnvironmentLight, ImageOfOneColourLightsAsTheSameBackground) {
    const Color sky{0.5f, 0.5f, 0.5f};
    Scene constant = test::sphereSeenFromMinusZ(test::pbr({1, 1, 1}, 0, 1, 0), 14);
    constant.background = sky;
    constant.flatten();
    Scene image = withEnvironmentTexture(constant);
    image.background = {0, 0, 0};
    const test::FunctionTextures texture(image, [sky](float, float) { return sky; });
    RenderSettings settings = test::pathPicture(24, 64);
    settings.maxBounces = 200;
    const test::ImageMean a = test::meanOverHits(test::renderPath(constant, settings));
    const test::ImageMean b = test::meanOverHits(test::renderPath(image, settings, &texture));
    std::printf("sphere under a background of 0.5: %.4f +- %.4f; under an image of 0.5: %.4f +- %.4f\n", a.mean,
                a.standardError, b.mean, b.standardError);
    EXPECT_NEAR(b.mean, 0.5, 4 * b.standardError + 1e-3);
    EXPECT_NEAR(b.mean, a.mean, 4 * std::hypot(a.standardError, b.standardError) + 1e-3);
}

// The irradiance on a plane facing up, E = integral of L cos, from a sky of 0.1 with a sun of
// 1000 (5 degrees in radius, 44 degrees above the horizon): sampling the image's distribution and
// sampling the sphere uniformly agree within their errors, and with the closed form (a cap of
// radius a around the unit axis w gives the integral of cos = w.y pi sin^2 a); the first has far
// less variance (measured 30 against 146,000).
TEST(EnvironmentLight, ImportanceSamplingAgreesWithUniformSamplingWithLessVariance) {
    const Vec3 sun = normalize(Vec3{0.3, std::sin(Real(0.7)), -0.6});
    const Scene scene = withEnvironmentTexture(Scene{});
    const test::FunctionTextures texture(scene, [sun](float s, float t) {
        const bool inSun = dot(equirectangularDirection(s, t), sun) > std::cos(Real(5.0 / 180 * kPi));
        return inSun ? Color{1000, 1000, 1000} : Color{0.1f, 0.1f, 0.1f};
    });
    const EnvironmentLight light(ShadingContext{scene, &texture});
    constexpr int kSamples = 1 << 16;
    double sum[2] = {}, sumSq[2] = {};
    for (int i = 0; i < kSamples; ++i) {
        SobolSampler sampler(1, 2, std::uint32_t(i), 0);
        const auto [u1, u2] = sampler.next2D();
        const EnvironmentSample important = light.sample(u1, u2);
        const Real z = 1 - 2 * u1, r = std::sqrt(std::max(Real(0), 1 - z * z));
        const Vec3 uniform{r * std::cos(2 * kPi * u2), z, r * std::sin(2 * kPi * u2)};
        const double estimates[2] = {important.pdf > 0 ? light.radiance(important.direction).g *
                                                             std::max(Real(0), important.direction.y) / important.pdf
                                                       : 0,
                                     light.radiance(uniform).g * std::max(Real(0), uniform.y) * 4 * kPi};
        for (int k = 0; k < 2; ++k) sum[k] += estimates[k], sumSq[k] += estimates[k] * estimates[k];
    }
    double mean[2], variance[2];
    for (int k = 0; k < 2; ++k) {
        mean[k] = sum[k] / kSamples;
        variance[k] = sumSq[k] / kSamples - mean[k] * mean[k];
    }
    const double error = std::sqrt((variance[0] + variance[1]) / kSamples);
    std::printf("irradiance: %.3f (variance %.3g) by the image's distribution, %.3f (variance %.3g) uniform\n", mean[0],
                variance[0], mean[1], variance[1]);
    EXPECT_NEAR(mean[0], mean[1], 4 * error);
    const double sunRadius = 5.0 / 180 * kPi;
    const double exact = (1000 - 0.1) * sun.y * kPi * std::pow(std::sin(sunRadius), 2) + 0.1 * kPi;
    EXPECT_NEAR(mean[0], exact, 0.005 * exact);
    EXPECT_LT(variance[0], 0.01 * variance[1]);
}

// <environment intensity rotation>: turned 90 degrees about +y, the image's centre (-z) lights
// from -x, times the intensity; its samples go where the turned sun is, with the density pdf() gives.
TEST(EnvironmentLight, RotationTurnsTheImageAndIntensityScalesIt) {
    Scene scene = withEnvironmentTexture(Scene{});
    scene.environment->intensity = 3;
    scene.environment->rotation = 90;
    const Vec3 imageSun{0, 0, -1};  // the image's centre
    const test::FunctionTextures texture(scene, [imageSun](float s, float t) {
        const bool inSun = dot(equirectangularDirection(s, t), imageSun) > Real(0.99);
        return inSun ? Color{100, 100, 100} : Color{0.5f, 0.25f, 1};
    });
    const EnvironmentLight light(ShadingContext{scene, &texture});
    EXPECT_EQ(light.radiance({-1, 0, 0}), (Color{300, 300, 300}));
    EXPECT_EQ(light.radiance({0, 0, -1}), (Color{1.5f, 0.75f, 3}));
    int towardsSun = 0;
    for (int i = 0; i < 256; ++i) {
        SobolSampler sampler(3, 4, std::uint32_t(i), 0);
        const auto [u1, u2] = sampler.next2D();
        const EnvironmentSample sample = light.sample(u1, u2);
        towardsSun += sample.direction.x < Real(-0.98);
        EXPECT_NEAR(light.pdf(sample.direction), sample.pdf, 1e-3 * sample.pdf);
    }
    EXPECT_GT(towardsSun, 128) << "the sun holds 60 % of the light";
}

namespace {

// A sky that is not uniform anywhere: a gradient above the horizon (0.2 + 0.8 y), a bright
// ground below it (3, which a surface facing up never sees), and a sun of `sun` (5 degrees in
// radius, 40 degrees above the horizon) added on top.
struct GradientSkyWithSun {
    static constexpr double kSunRadius = 5.0 / 180 * kPi;
    Vec3 sunDirection = normalize(Vec3{0.4, std::sin(Real(0.7)), -0.5});
    float sun = 100;

    Color operator()(float s, float t) const {
        const Vec3 d = equirectangularDirection(s, t);
        const float sky = d.y > 0 ? 0.2f + 0.8f * float(d.y) : 3.0f;
        const bool inSun = dot(d, sunDirection) > std::cos(Real(kSunRadius));
        return Color{1, 1, 1} * (sky + (inSun ? sun : 0.0f));
    }
    // The irradiance on a surface facing +y: the integral of L cos over the upper hemisphere,
    // 0.2 pi + 0.8 (2 pi / 3), and the sun's cap, pi sin^2(radius) times its axis' height.
    double irradianceFacingUp() const {
        return 0.2 * kPi + 0.8 * 2 * kPi / 3 + sun * kPi * std::pow(std::sin(kSunRadius), 2) * double(sunDirection.y);
    }
};

}  // namespace

// A furnace-style check of the environment's importance sampling in the path tracer: a Lambertian
// floor of albedo 0.5 under the sky above, with nothing else in the scene, shows 0.5 E / pi on
// every pixel (one bounce: nothing is reflected back onto it). The light samples follow the
// image's distribution and the BSDF's hit the sky; multiple importance sampling weighs the two
// by the densities sample() and pdf() give, so a density that is not the samples' own (a wrong
// sin(theta) in either) shows as a brighter or darker floor.
TEST(EnvironmentLight, LambertianFloorUnderANonUniformSkyShowsItsIrradianceTimesAlbedoOverPi) {
    Scene scene;
    scene.camera.origin = {0, 3, 2};
    scene.camera.destination = {0, 0, 0};
    scene.camera.fovDegrees = 30;
    const auto floor = test::addMaterial(scene, test::pbr({0.5f, 0.5f, 0.5f}, 0, 1, 0));
    test::addQuad(scene, {-20, 0, -20}, {20, 0, -20}, {20, 0, 20}, {-20, 0, 20}, floor);
    scene.flatten();
    scene = withEnvironmentTexture(scene);
    const GradientSkyWithSun sky;
    const test::FunctionTextures texture(scene, sky);
    const test::ImageMean floorSeen = test::meanOverHits(test::renderPath(scene, test::pathPicture(16, 32), &texture));
    const double expected = 0.5 * sky.irradianceFacingUp() / kPi;
    std::printf("floor under the sky: %.4f +- %.4f, expected %.4f\n", floorSeen.mean, floorSeen.standardError,
                expected);
    EXPECT_NEAR(floorSeen.mean, expected, 4 * floorSeen.standardError + 1e-3 * expected);
}

// The density next-event estimation gives an environment sample is the one multiple importance
// sampling asks for when a BSDF's ray finds the same direction (LightDistribution::pdfEnvironment:
// the environment's share of the choices times EnvironmentLight::pdf), beside a point light that
// takes its own share of the samples.
TEST(EnvironmentLight, SampledDensityIsTheOneMultipleImportanceSamplingAsksFor) {
    Scene scene;
    const auto grey = test::addMaterial(scene, test::pbr({0.5f, 0.5f, 0.5f}, 0, 1, 0));
    test::addQuad(scene, {-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, grey);
    scene.lights.push_back(Light{.position = {0, 2, 0}, .color = {5, 5, 5}, .falloff = Light::Falloff::InverseSquare});
    scene.flatten();
    scene = withEnvironmentTexture(scene);
    const test::FunctionTextures texture(scene, GradientSkyWithSun{});
    const LightDistribution lights({scene, &texture});
    const Vec3 from{0.2, 0.5, 0.1}, normal{0, 1, 0};
    // In float a sampled direction, rounded, can fall into the image's next cell, of another
    // density (seen once in 4096, next to a pole); a density without its Jacobian differs nearly
    // everywhere.
    int skySamples = 0, differing = 0;
    for (int i = 0; i < 4096; ++i) {
        SobolSampler sampler(5, 6, std::uint32_t(i), 0);
        const Real pick = sampler.next1D();
        const auto [u1, u2] = sampler.next2D();
        const std::optional<LightSample> light = lights.sample(from, normal, pick, u1, u2);
        if (!light || light->source != LightSample::Source::Environment) continue;
        ++skySamples;
        if (std::abs(lights.pdfEnvironment(light->direction) - light->pdf) > 1e-3 * light->pdf) ++differing;
    }
    const int allowed = std::is_same_v<Real, double> ? 0 : skySamples / 200;
    EXPECT_LE(differing, allowed);
    EXPECT_GT(skySamples, 1000);
    EXPECT_LT(skySamples, 4096) << "the point light takes a share";
}
