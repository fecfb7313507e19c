// Adaptive subsampling (thesis 2.3): few camera rays where the picture is flat, every edge and
// every object a corner sees kept, the same bits for any thread count and region split.
#include <cmath>
#include <cstring>

#include "accel/naive.h"
#include "core/error.h"
#include "render/renderer.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// A material that shows only its emission (no lights, no ambient term): flat colours, so a
// full render and an interpolated one can be compared exactly.
Material glowing(const Color& emission, std::optional<std::uint32_t> texture = {}) {
    return {.name = "glow", .phong = {.ambient = 0, .diffuse = 0}, .emission = {.color = emission, .texture = texture}};
}

Scene facingCamera() {
    Scene s;
    s.background = {0.1f, 0.2f, 0.3f};
    s.camera.origin = {0, 0, -10};
    s.camera.destination = {0, 0, 0};
    s.camera.fovDegrees = 20;
    return s;
}

// A black and white checkerboard filling the view, its squares (about 22 pixels at 128 pixels
// across: the view is 3.5 units wide) larger than the 8-pixel grid and not aligned with it.
Scene checkerboard() {
    Scene s = facingCamera();
    s.textures.push_back({.name = "checker", .kind = Texture::Kind::Checker, .size = 0.6f});
    const auto m = test::addMaterial(s, glowing({1, 1, 1}, 0));
    test::addQuad(s, {-5, -5, 0}, {-5, 5, 0}, {5, 5, 0}, {5, -5, 0}, m);
    s.flatten();
    return s;
}

// A sphere about 5 pixels across (at 64 pixels across) in the middle of the view, over the background.
Scene smallSphere(const Color& emission) {
    Scene s = facingCamera();
    s.looseObjects.add<Sphere>({{0, 0, 0}, 0.14}, test::addMaterial(s, glowing(emission)));
    s.flatten();
    return s;
}

RenderSettings adaptive(int width, int height, int grid = 8) {
    RenderSettings r = test::picture(width, height);
    r.adaptiveGrid = grid;
    return r;
}

// The largest difference of any channel of any pixel between two renders of the same window.
float largestDifference(const Framebuffer& a, const Framebuffer& b) {
    float largest = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        const Color &p = a.pixels()[i], &q = b.pixels()[i];
        largest = std::max({largest, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b),
                            std::abs(a.alphas()[i] - b.alphas()[i])});
    }
    return largest;
}

Framebuffer renderFull(const Scene& s, const Accelerator& accel, RenderSettings settings) {
    settings.adaptiveGrid = 0;
    RenderStats stats;
    return render(s, accel, settings, stats);
}

}  // namespace

TEST(RenderAdaptive, AFlatPictureTakesOneCameraRayPerCell) {
    const Scene s = facingCamera();  // nothing but the background
    const NaiveAccelerator accel(s.primitives);
    for (const int grid : {4, 8, 16}) {
        RenderStats stats;
        const Framebuffer image = render(s, accel, adaptive(64, 48, grid), stats);
        // The corners of (64 / grid) x (48 / grid) cells, the image's edge closing the last ones.
        EXPECT_EQ(stats.counters.camera.rays, std::uint64_t((64 / grid + 1) * (48 / grid + 1))) << grid;
        EXPECT_EQ(stats.counters.interpolatedPixels, 64u * 48u - stats.counters.camera.rays) << grid;
        for (const Color& c : image.pixels()) ASSERT_TRUE(sameBits(c, s.background));
    }
}

TEST(RenderAdaptive, KeepsEveryEdgeOfACheckerboard) {
    const Scene s = checkerboard();
    const NaiveAccelerator accel(s.primitives);
    RenderStats stats;
    const Framebuffer image = render(s, accel, adaptive(128, 96), stats);
    EXPECT_EQ(largestDifference(image, renderFull(s, accel, adaptive(128, 96))), 0.0f);
    EXPECT_LT(stats.counters.camera.rays, 128u * 96u / 2) << "the squares' insides are interpolated";
}

TEST(RenderAdaptive, TheObjectTestKeepsASmallObjectOfTheBackgroundsColour) {
    // The sphere glows in almost the background's colour: only the object test tells them apart.
    const Scene s = smallSphere(facingCamera().background * 1.01f);
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = adaptive(64, 48);
    settings.adaptiveThreshold = 1e9f;  // no colour difference splits a cell
    RenderStats stats;
    const Framebuffer image = render(s, accel, settings, stats);
    const Framebuffer full = renderFull(s, accel, settings);
    int covered = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            covered += full.alphaAt(x, y) == 1;
            ASSERT_EQ(image.alphaAt(x, y), full.alphaAt(x, y)) << x << "," << y;
        }
    EXPECT_GT(covered, 9) << "the sphere is smaller than a cell but more than a pixel";
    EXPECT_LT(covered, 64);
    EXPECT_EQ(largestDifference(image, full), 0.0f);
}

TEST(RenderAdaptive, ThresholdZeroTracesEveryPixelAsAFullRenderDoes) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = adaptive(70, 40);
    settings.shadows = true;
    settings.pixelSamples = 2;  // -S inside the traced pixels
    settings.softShadows = settings.glossyReflections = true;
    settings.distributedSamples = 3;
    settings.adaptiveThreshold = 0;
    RenderStats stats;
    const Framebuffer image = render(s, accel, settings, stats);
    const Framebuffer full = renderFull(s, accel, settings);
    for (std::size_t i = 0; i < full.pixels().size(); ++i)
        ASSERT_TRUE(sameBits(image.pixels()[i], full.pixels()[i])) << "pixel " << i;
    EXPECT_EQ(image.alphas(), full.alphas());
    EXPECT_EQ(stats.counters.interpolatedPixels, 0u);
}

TEST(RenderAdaptive, RegionsAndThreadCountsGiveTheSameBits) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    for (const int width : {70, 65}) {  // 65: the last column is a multiple of the grid
        RenderSettings settings = adaptive(width, 40);
        settings.shadows = true;
        settings.pixelSamples = 2;
        settings.adaptiveThreshold = 0.05f;
        settings.threads = 1;
        RenderStats one, two;
        const Framebuffer full = render(s, accel, settings, one);
        settings.threads = 2;
        const Framebuffer twoThreads = render(s, accel, settings, two);
        EXPECT_GT(one.counters.interpolatedPixels, 0u);
        EXPECT_EQ(one.counters.camera.rays, two.counters.camera.rays);
        for (std::size_t i = 0; i < full.pixels().size(); ++i)
            ASSERT_TRUE(sameBits(full.pixels()[i], twoThreads.pixels()[i])) << "pixel " << i;
        const int mx = 33, my = 17;  // off the grid on purpose
        for (const PixelWindow& w : {PixelWindow{0, 0, mx, my}, PixelWindow{mx, 0, width, my},
                                     PixelWindow{0, my, mx, 40}, PixelWindow{mx, my, width, 40}}) {
            settings.region = w;
            RenderStats stats;
            const Framebuffer tile = render(s, accel, settings, stats);
            for (int y = w.y0; y < w.y1; ++y)
                for (int x = w.x0; x < w.x1; ++x) {
                    ASSERT_TRUE(sameBits(tile.at(x, y), full.at(x, y))) << x << "," << y;
                    ASSERT_EQ(tile.alphaAt(x, y), full.alphaAt(x, y)) << x << "," << y;
                }
        }
    }
}

TEST(RenderAdaptive, RejectsAGridThatIsNoPowerOfTwoAndAovs) {
    const Scene s = facingCamera();
    const NaiveAccelerator accel(s.primitives);
    RenderStats stats;
    RenderSettings settings = adaptive(16, 16, 6);
    EXPECT_THROW(render(s, accel, settings, stats), InputError);
    settings = adaptive(16, 16, 1);
    EXPECT_THROW(render(s, accel, settings, stats), InputError);
    settings = adaptive(16, 16);
    settings.aovs = {Aov::Z};
    EXPECT_THROW(render(s, accel, settings, stats), InputError);
}
