// The path tracer's sky (render/lights/environment_light.h): the equirectangular mapping, an image of
// one colour lighting as the same background colour does, and importance sampling of a small
// bright spot: the same mean as uniform sampling, with far less variance.
#include <cmath>
#include <cstdio>
#include <functional>

#include "render/lights/environment_light.h"
#include "render/sampling.h"
#include "render/sobol_sampler.h"
#include "render_path_util.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// Every image texture is the function `value` of the texture coordinates.
class FunctionTextures : public ImageTextures {
public:
    FunctionTextures(const Scene& scene, std::function<Color(float, float)> value)
        : ImageTextures(scene), value_(std::move(value)) {}
    Color lookup(std::uint32_t, const TexCoord& at) const override { return value_(at.s, at.t); }
    Color data(std::uint32_t, const TexCoord& at) const override { return value_(at.s, at.t); }
    float alpha(std::uint32_t, float, float, bool) const override { return 1; }
    bool hasAlpha(std::uint32_t, bool) const override { return false; }

private:
    std::function<Color(float, float)> value_;
};

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
    const FunctionTextures texture(image, [sky](float, float) { return sky; });
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
    const FunctionTextures texture(scene, [sun](float s, float t) {
        const bool inSun = dot(equirectangularDirection(s, t), sun) > std::cos(Real(5.0 / 180 * kPi));
        return inSun ? Color{1000, 1000, 1000} : Color{0.1f, 0.1f, 0.1f};
    });
    const EnvironmentLight light(scene, &texture);
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
    const FunctionTextures texture(scene, [imageSun](float s, float t) {
        const bool inSun = dot(equirectangularDirection(s, t), imageSun) > Real(0.99);
        return inSun ? Color{100, 100, 100} : Color{0.5f, 0.25f, 1};
    });
    const EnvironmentLight light(scene, &texture);
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
