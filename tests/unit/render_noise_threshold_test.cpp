// Noise-adaptive sampling, --noise-threshold (render/film/noise_threshold.h): where a pixel stops, that
// it stops after the same sample for any thread count or region split, and that the samples it
// saves are worth it: at the same total of samples, the error against a converged reference is no
// larger than uniform sampling's.
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "render/film/noise_threshold.h"
#include "render_path_util.h"
#include "test_util.h"

using namespace rt;

namespace {

RenderSettings adaptivePicture(int size, int maxSamples, float threshold) {
    RenderSettings r = test::pathPicture(size, maxSamples);
    r.noiseThreshold = threshold;
    return r;
}

float channel(const Color& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : c.b; }

// The mean over pixels and channels of |image - reference| / (reference + 0.01): the relative
// error bench/compare_images.py reports.
double meanRelativeError(const Framebuffer& image, const Framebuffer& reference) {
    double sum = 0;
    for (std::size_t i = 0; i < image.pixels().size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double x = channel(image.pixels()[i], c), r = channel(reference.pixels()[i], c);
            sum += std::abs(x - r) / (r + 0.01);
        }
    return sum / double(3 * image.pixels().size());
}

// The box seen from further back, so that the black around it (converged at once) and the lamp
// (constant) stand beside walls of very different noise: what the threshold is for.
Scene boxInTheDark() {
    Scene s = test::boxWithLightPanel();
    s.camera.origin = {0, 1, 5};
    return s;
}

}  // namespace

TEST(RenderNoiseThreshold, MinimumSamplesFollowCyclesRule) {
    EXPECT_EQ(automaticMinSamples(0.1f), 32);
    EXPECT_EQ(automaticMinSamples(0.01f), 64);
    EXPECT_EQ(automaticMinSamples(1000.0f), 4);
    RenderSettings s = adaptivePicture(4, 64, 0.01f);
    EXPECT_EQ(NoiseThreshold(s).minSamples(), 64);
    s.adaptiveMinSamples = 5;
    EXPECT_EQ(NoiseThreshold(s).minSamples(), 5);
}

TEST(RenderNoiseThreshold, APixelIsJudgedAtTheMinimumAndThenEveryRound) {
    RenderSettings settings = adaptivePicture(4, 64, 0.05f);
    settings.adaptiveMinSamples = 20;
    const NoiseThreshold noise(settings);
    PixelEstimate constant;
    for (int i = 0; i < 16; ++i) constant.add({0.5f, 0.5f, 0.5f}, true);
    EXPECT_FALSE(noise.stopped(constant)) << "below the minimum";
    for (int i = 16; i < 20; ++i) constant.add({0.5f, 0.5f, 0.5f}, true);
    EXPECT_FALSE(noise.stopped(constant)) << "20 samples: not a round";
    for (int i = 20; i < 32; ++i) constant.add({0.5f, 0.5f, 0.5f}, true);
    EXPECT_TRUE(noise.stopped(constant)) << "no noise at the first round";

    PixelEstimate noisy;  // 0 and 1 alternating: luminance mean 0.5, standard error 0.5 / sqrt(n - 1)
    for (int i = 0; i < 32; ++i) noisy.add({float(i % 2), float(i % 2), float(i % 2)}, true);
    EXPECT_NEAR(NoiseThreshold::relativeError(noisy), std::sqrt(0.25 * 32 / 31 / 32) / 0.51, 1e-5);
    EXPECT_FALSE(noise.stopped(noisy));
}

TEST(RenderNoiseThreshold, TheWhittedIntegratorRefusesIt) {
    RenderSettings s = adaptivePicture(4, 16, 0.05f);
    s.integrator = Integrator::Whitted;
    EXPECT_THROW(validate(s), InputError);
    s.integrator = Integrator::Path;
    s.adaptiveMinSamples = 1;
    EXPECT_THROW(validate(s), InputError);
    s.adaptiveMinSamples = 0;
    s.noiseThreshold = -1;
    EXPECT_THROW(validate(s), InputError);
}

// Every pixel stops after the same sample whatever the threads or the region: the same bits, and
// the samples AOV shows the counts: a round (a multiple of 16) from the minimum on, or -S.
TEST(RenderNoiseThreshold, SameBitsForAnyThreadCountAndRegionSplit) {
    const Scene s = boxInTheDark();
    RenderSettings one = adaptivePicture(24, 64, 0.05f);
    one.adaptiveMinSamples = 8;
    one.threads = 1;
    one.aovs = {Aov::Samples};
    test::Rendered whole = test::renderNaive(s, one);
    RenderSettings two = one;
    two.threads = 2;
    const test::Rendered parallel = test::renderNaive(s, two);
    EXPECT_EQ(0, std::memcmp(whole.image.pixels().data(), parallel.image.pixels().data(),
                             whole.image.pixels().size() * sizeof(Color)));
    EXPECT_EQ(whole.stats.samplesTaken, parallel.stats.samplesTaken);
    RenderSettings part = two;
    part.region = PixelWindow{5, 3, 17, 20};
    test::Rendered region = test::renderNaive(s, part);
    int stoppedEarly = 0, tookAll = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            const float n = whole.image.aovsAt(x, y)->samples;
            ASSERT_TRUE(n == 64 || (n >= 8 && int(n) % kNoiseCheckInterval == 0)) << n;
            stoppedEarly += n < 64;
            tookAll += n == 64;
            const PixelWindow& r = *part.region;
            if (x < r.x0 || x >= r.x1 || y < r.y0 || y >= r.y1) continue;
            ASSERT_EQ(region.image.at(x, y), whole.image.at(x, y)) << x << "," << y;
            ASSERT_EQ(region.image.aovsAt(x, y)->samples, n) << x << "," << y;
        }
    EXPECT_GT(stoppedEarly, 0);
    EXPECT_GT(tookAll, 0) << "the threshold should keep the noisiest pixels sampling";
    EXPECT_LT(whole.stats.samplesTaken, 24u * 24u * 64u);
    EXPECT_EQ(whole.stats.samplesPerPixel, 64);
}

// At the same total of samples, the adaptive picture is no further from a converged reference
// than the uniform one, and a lower threshold brings it closer.
TEST(RenderNoiseThreshold, ConvergesAtLeastAsWellAsUniformSamplingAtTheSameSamples) {
    const Scene s = boxInTheDark();
    const Framebuffer reference = test::renderPath(s, test::pathPicture(24, 1024));
    const auto renderAdaptive = [&](float threshold) {
        RenderSettings r = adaptivePicture(24, 256, threshold);
        r.seed = 3;  // noise independent of the reference's
        return test::renderNaive(s, r);
    };
    const test::Rendered coarse = renderAdaptive(0.1f), fine = renderAdaptive(0.04f);
    const int uniformSamples = int(std::lround(double(fine.stats.samplesTaken) / (24.0 * 24.0)));
    RenderSettings u = test::pathPicture(24, uniformSamples);
    u.seed = 3;
    const Framebuffer uniform = test::renderPath(s, u);
    const double eCoarse = meanRelativeError(coarse.image, reference), eFine = meanRelativeError(fine.image, reference),
                 eUniform = meanRelativeError(uniform, reference);
    std::printf("mean relative error: threshold 0.1 %.4f (%llu samples), 0.04 %.4f (%llu), uniform %d a pixel %.4f\n",
                eCoarse, static_cast<unsigned long long>(coarse.stats.samplesTaken), eFine,
                static_cast<unsigned long long>(fine.stats.samplesTaken), uniformSamples, eUniform);
    EXPECT_LT(eFine, eCoarse);
    EXPECT_LT(fine.stats.samplesTaken, 24u * 24u * 256u);
    EXPECT_LE(eFine, 1.05 * eUniform);
}
