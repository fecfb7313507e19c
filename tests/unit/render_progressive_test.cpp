// The renderer's passes, --time-limit, the variance AOV and the estimate -p prints
// (render/renderer.h, render/film/pixel_estimate.h).
#include <atomic>
#include <cmath>
#include <cstring>

#include "accel/naive.h"
#include "core/error.h"
#include "render/film/pixel_estimate.h"
#include "render/integrators/path_tracer.h"
#include "render/memory_estimate.h"
#include "render/renderer.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

RenderSettings pathPicture(int width, int height, int samples) {
    RenderSettings r = test::picture(width, height);
    r.integrator = Integrator::Path;
    r.pixelSamples = samples;
    return r;
}

void expectSameBits(const Framebuffer& a, const Framebuffer& b) {
    ASSERT_EQ(a.pixels().size(), b.pixels().size());
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        ASSERT_TRUE(sameBits(a.pixels()[i], b.pixels()[i])) << "pixel " << i;
    EXPECT_EQ(a.alphas(), b.alphas());
}

// The mean over the picture of the variance AOV's green channel.
double meanVariance(const Framebuffer& image) {
    double sum = 0;
    for (const PixelAovs& a : image.aovs()) sum += a.variance.g;
    return sum / double(image.aovs().size());
}

}  // namespace

TEST(RenderProgressive, PassesGiveTheBitsOfEveryPixelsSamplesInOneLoop) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = pathPicture(37, 21, 5);
    settings.threads = 2;
    RenderStats stats;
    const Framebuffer image = render(s, accel, settings, stats);
    EXPECT_EQ(stats.samplesPerPixel, 5);
    EXPECT_FALSE(stats.timeLimitReached);
    const PathTracer tracer(s, accel, settings);
    RenderCounters counters;
    for (int y = 0; y < 21; ++y)
        for (int x = 0; x < 37; ++x) {
            float coverage;
            const Color c = tracer.pixel(x, y, counters, coverage);
            ASSERT_TRUE(sameBits(c, image.at(x, y))) << x << "," << y;
            ASSERT_EQ(coverage, image.alphaAt(x, y)) << x << "," << y;
        }
    EXPECT_EQ(counters.rays(), stats.counters.rays());
}

TEST(RenderProgressive, AGenerousTimeLimitChangesNoBit) {
    const Scene s = test::spheresOnFloor();
    for (const Integrator integrator : {Integrator::Path, Integrator::Whitted}) {
        RenderSettings settings = pathPicture(40, 24, 3);
        settings.integrator = integrator;
        settings.shadows = true;
        const test::Rendered free = test::renderNaive(s, settings);
        settings.timeLimitSeconds = 1e6;
        const test::Rendered limited = test::renderNaive(s, settings);
        expectSameBits(free.image, limited.image);
        EXPECT_EQ(limited.stats.samplesPerPixel, 3);
        EXPECT_FALSE(limited.stats.timeLimitReached);
    }
}

// Stopped during the third pass (one thread, so the stop falls between the same blocks each
// time): the picture is the two whole passes, the bits of -S 2.
TEST(RenderProgressive, AStoppedPassIsDroppedWhole) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = pathPicture(70, 40, 6);  // three blocks across, two down
    settings.threads = 1;
    settings.aovs = parseAovList("all");
    std::atomic<bool> stop{false};
    const std::uint64_t pixels = 70 * 40;
    RenderStats stats;
    const Framebuffer stopped = render(
        s, accel, settings, stats, [&](std::uint64_t done, std::uint64_t) { stop = stop || done > 2 * pixels + 100; },
        RenderWatch{{}, &stop, {}});
    EXPECT_EQ(stats.samplesPerPixel, 2);
    settings.pixelSamples = 2;
    const Framebuffer twoPasses = test::renderNaive(s, settings).image;
    expectSameBits(stopped, twoPasses);
    ASSERT_EQ(stopped.aovs().size(), twoPasses.aovs().size());
    EXPECT_EQ(std::memcmp(stopped.aovs().data(), twoPasses.aovs().data(), sizeof(PixelAovs) * stopped.aovs().size()), 0)
        << "the AOVs of the third pass are dropped too";
}

// An end asked for during pass 3 (rt-render's SIGUSR1) ends the render after that pass, whole:
// the bits of -S 3. The path tracer asks after every pass but the last; the Whitted tracer never.
TEST(RenderProgressive, AnEndAskedForKeepsThePassUnderWay) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = pathPicture(70, 40, 6);
    settings.threads = 2;
    std::atomic<bool> asked{false};
    int questions = 0;
    RenderWatch watch;
    watch.endAfterPass = [&] {
        ++questions;
        return asked.load();
    };
    const std::uint64_t pixels = 70 * 40;
    RenderStats stats;
    const Framebuffer ended = render(
        s, accel, settings, stats, [&](std::uint64_t done, std::uint64_t) { asked = asked || done > 2 * pixels + 100; },
        watch);
    EXPECT_EQ(stats.samplesPerPixel, 3);
    EXPECT_EQ(questions, 3);
    EXPECT_FALSE(stats.timeLimitReached);
    settings.pixelSamples = 3;
    expectSameBits(ended, test::renderNaive(s, settings).image);

    asked = true;
    questions = 0;
    settings.integrator = Integrator::Whitted;
    render(s, accel, settings, stats, {}, watch);
    EXPECT_EQ(stats.samplesPerPixel, 3) << "the Whitted tracer takes every sample";
    EXPECT_EQ(questions, 0);
}

// A limit that has passed before the first pixel: nothing whole, in either integrator.
TEST(RenderProgressive, ALimitThatRunsOutFirstLeavesNoWholePass) {
    const Scene s = test::spheresOnFloor();
    for (const Integrator integrator : {Integrator::Path, Integrator::Whitted}) {
        RenderSettings settings = pathPicture(40, 24, 4);
        settings.integrator = integrator;
        settings.timeLimitSeconds = 1e-300;
        const test::Rendered r = test::renderNaive(s, settings);
        EXPECT_EQ(r.stats.samplesPerPixel, 0);
        EXPECT_TRUE(r.stats.timeLimitReached);
        EXPECT_LT(r.stats.counters.camera.rays, 40u * 24u);  // it stopped at once
    }
}

TEST(RenderProgressive, TimeLimitsAreChecked) {
    RenderSettings settings = pathPicture(4, 4, 1);
    settings.timeLimitSeconds = -1;
    EXPECT_THROW(validate(settings), InputError);
    settings.timeLimitSeconds = std::nan("");
    EXPECT_THROW(validate(settings), InputError);
    settings.timeLimitSeconds = 2e9;
    EXPECT_THROW(validate(settings), InputError);
}

TEST(RenderProgressive, PassesAreCountedInTheMemoryEstimate) {
    RenderSettings settings = pathPicture(100, 100, 4);
    const std::uint64_t path = estimateRenderMemory(settings, 0, true).image;
    settings.integrator = Integrator::Whitted;
    EXPECT_EQ(path - estimateRenderMemory(settings, 0, true).image, 100u * 100u * kPathPassBytesPerPixel);
    EXPECT_GE(kPathPassBytesPerPixel, 2 * sizeof(PixelEstimate));
    EXPECT_GE(kPathAovPassBytesPerPixel, 2 * sizeof(AovSums));
    settings.aovs = {Aov::Variance};
    const std::uint64_t withAovs = estimateRenderMemory(settings, 0, true).image;
    settings.integrator = Integrator::Path;
    EXPECT_EQ(estimateRenderMemory(settings, 0, true).image - withAovs,
              100u * 100u * (kPathPassBytesPerPixel + kPathAovPassBytesPerPixel));
}

TEST(PixelEstimate, WelfordGivesTheSampleVarianceOverN) {
    PixelEstimate e;
    for (const float v : {1.0f, 2.0f, 4.0f, 5.0f}) EXPECT_TRUE(e.add({v, 2 * v, 0.3f}, v > 1));
    EXPECT_FLOAT_EQ(e.mean().r, 3.0f);
    // sample variance (4 + 1 + 1 + 4) / 3, over n = 4
    EXPECT_FLOAT_EQ(e.varianceOfMean().r, 10.0f / 3 / 4);
    EXPECT_FLOAT_EQ(e.varianceOfMean().g, 4 * 10.0f / 3 / 4);
    EXPECT_EQ(e.varianceOfMean().b, 0.0f);  // a constant channel: exactly 0
    EXPECT_FLOAT_EQ(e.coverage(), 0.75f);
    EXPECT_FALSE(e.add({std::nanf(""), 0, 0}, true));  // counted as black
    EXPECT_EQ(e.samples, 5);
}

// The renderer's passes leave the variance out when nothing reads it; the mean and coverage
// must not notice.
TEST(PixelEstimate, WithoutTheVarianceTheMeanAndCoverageKeepTheirBits) {
    PixelEstimate with, without;
    for (const float v : {0.1f, 2.3f, 1e30f, 0.7f, std::nanf(""), 3.9f}) {
        const Color c{v, 0.5f * v, 1 / v};
        EXPECT_EQ(with.add(c, v > 1), without.add(c, v > 1, false)) << v;
    }
    EXPECT_TRUE(sameBits(with.mean(), without.mean()));
    EXPECT_EQ(with.coverage(), without.coverage());
    EXPECT_EQ(without.samples, 6);
    EXPECT_EQ(without.varianceOfMean(), Color{});  // not tracked
}

TEST(RenderVariance, AConstantPictureHasNone) {
    for (const Integrator integrator : {Integrator::Path, Integrator::Whitted}) {
        Scene s = test::spheresOnFloor();
        s.camera.destination = {0, 20, 0};  // the sky alone
        RenderSettings settings = pathPicture(16, 8, 8);
        settings.integrator = integrator;
        settings.aovs = {Aov::Variance};
        const Framebuffer image = test::renderNaive(s, settings).image;
        for (const PixelAovs& a : image.aovs()) ASSERT_EQ(a.variance, Color{});
        EXPECT_EQ(image.alphas(), std::vector<float>(image.alphas().size(), 0.0f));
    }
}

// The variance of a mean of N samples falls as 1/N: four times the samples, a quarter of it.
TEST(RenderVariance, FallsAsOneOverTheSamples) {
    const Scene s = test::spheresOnFloor();
    RenderSettings settings = pathPicture(24, 16, 16);
    settings.aovs = {Aov::Variance};
    const test::Rendered few = test::renderNaive(s, settings);
    settings.pixelSamples = 64;
    const test::Rendered many = test::renderNaive(s, settings);
    const double ratio = meanVariance(few.image) / meanVariance(many.image);
    EXPECT_GT(meanVariance(many.image), 0);
    EXPECT_GT(ratio, 3.0);
    EXPECT_LT(ratio, 5.3);
    // The AOV does not change the colour.
    settings.aovs.clear();
    expectSameBits(many.image, test::renderNaive(s, settings).image);
}

// The estimate's counts come from the probe alone (no time cap here): they grow with the
// lights each hit sends shadow rays to, the pixels and the samples.
TEST(RenderEstimate, GrowsWithLightsPixelsAndSamples) {
    const auto lights = [](int n) {
        Scene s =
            test::sphereSeenFromMinusZ(Material{.name = "white", .color = {1, 1, 1}, .phong = {.diffuse = 1}}, 14);
        for (int i = 0; i < n; ++i) s.lights.push_back({{0, 0, -5}, {0.1f, 0.1f, 0.1f}, 0});  // seen by every hit
        s.flatten();
        return s;
    };
    RenderSettings settings = test::picture(32, 24);
    settings.shadows = true;
    settings.threads = 3;
    const auto estimate = [&](const Scene& s, const RenderSettings& r) {
        const NaiveAccelerator accel(s.primitives);
        return estimateRender(s, accel, r, 64, 1e9);
    };
    const Scene one = lights(1), eight = lights(8);
    const RenderEstimate e1 = estimate(one, settings), e8 = estimate(eight, settings);
    EXPECT_EQ(e1.probePixels, 64u);
    EXPECT_GT(e1.probe.shadow.rays, 0u);
    EXPECT_EQ(e8.probe.shadow.rays, 8 * e1.probe.shadow.rays);
    EXPECT_NEAR(e8.rays - e1.cameraSamples, 8 * (e1.rays - e1.cameraSamples), 1e-6 * e8.rays);
    EXPECT_EQ(e1.cameraSamples, 32u * 24u);

    RenderSettings twice = settings;
    twice.pixelSamples = 2;
    const RenderEstimate samples = estimate(one, twice);
    EXPECT_DOUBLE_EQ(samples.rays, 2 * e1.rays);
    EXPECT_DOUBLE_EQ(samples.intersectionTests, 2 * e1.intersectionTests);
    twice = settings;
    twice.width = 64;
    twice.height = 48;
    const RenderEstimate pixels = estimate(one, twice);
    EXPECT_EQ(pixels.cameraSamples, 4 * e1.cameraSamples);
    EXPECT_NEAR(pixels.rays / e1.rays, 4.0, 0.4);  // other pixels probed, about the same mix
    EXPECT_GT(e1.seconds, 0);
    EXPECT_EQ(e1.threads, 3);
}

// A probe out of time still takes one pixel, and says how many it took.
TEST(RenderEstimate, AProbeOutOfTimeTakesOnePixel) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    const RenderEstimate e = estimateRender(s, accel, test::picture(40, 30), 256, 0);
    EXPECT_EQ(e.probePixels, 1u);
    EXPECT_GT(e.rays, 0);
}
