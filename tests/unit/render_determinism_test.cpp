// The image is the same bits whatever the thread count and however it is split into regions.
#include <cstring>

#include "accel/naive.h"
#include "render/renderer.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// Everything random switched on: jittered supersampling, soft shadows, glossy reflections.
RenderSettings distributed() {
    RenderSettings r;
    r.width = 70;  // not a multiple of the block size
    r.height = 40;
    r.shadows = true;
    r.reflectionDepth = 3;
    r.pixelSamples = 2;
    r.softShadows = r.glossyReflections = true;
    r.distributedSamples = 3;
    return r;
}

}  // namespace

TEST(RenderDeterminism, OneAndTwoThreadsGiveTheSameBits) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = distributed();
    RenderStats one, two;
    settings.threads = 1;
    const Framebuffer a = render(s, accel, settings, one);
    settings.threads = 2;
    const Framebuffer b = render(s, accel, settings, two);
    ASSERT_EQ(a.pixels().size(), b.pixels().size());
    for (std::size_t i = 0; i < a.pixels().size(); ++i)
        ASSERT_TRUE(sameBits(a.pixels()[i], b.pixels()[i])) << "pixel " << i;
    EXPECT_EQ(a.alphas(), b.alphas());
    EXPECT_EQ(one.counters.rays(), two.counters.rays());
    EXPECT_EQ(one.counters.total().intersectionTests, two.counters.total().intersectionTests);
    EXPECT_EQ(two.threads, 2);
}

TEST(RenderDeterminism, FourRegionsEqualTheFullRender) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = distributed();
    RenderStats stats;
    const Framebuffer full = render(s, accel, settings, stats);
    EXPECT_TRUE(full.isFullImage());
    const int mx = 33, my = 17;  // off the block grid on purpose
    for (const PixelWindow& w : {PixelWindow{0, 0, mx, my}, PixelWindow{mx, 0, 70, my}, PixelWindow{0, my, mx, 40},
                                 PixelWindow{mx, my, 70, 40}}) {
        settings.region = w;
        const Framebuffer tile = render(s, accel, settings, stats);
        EXPECT_EQ(tile.window(), w);
        EXPECT_EQ(tile.pixels().size(), std::size_t(w.width() * w.height()));
        for (int y = w.y0; y < w.y1; ++y)
            for (int x = w.x0; x < w.x1; ++x) {
                ASSERT_TRUE(sameBits(tile.at(x, y), full.at(x, y))) << x << "," << y;
                ASSERT_EQ(tile.alphaAt(x, y), full.alphaAt(x, y)) << x << "," << y;
            }
    }
}

TEST(RenderDeterminism, ProgressReportsEveryBlockOnce) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings;
    settings.width = 70;
    settings.height = 40;
    settings.threads = 2;
    settings.pixelSamples = 2;
    int calls = 0;
    std::uint64_t last = 0, reportedTotal = 0;
    RenderStats stats;
    render(s, accel, settings, stats, [&](std::uint64_t done, std::uint64_t total) {
        ++calls;
        // Each block adds its own samples: full 32x32 blocks or the smaller edge blocks (6x32, 32x8, 6x8).
        const std::uint64_t added = done - last;
        EXPECT_TRUE(added == 32 * 32 * 2 || added == 6 * 32 * 2 || added == 32 * 8 * 2 || added == 6 * 8 * 2) << added;
        last = done;
        reportedTotal = total;
    });
    EXPECT_EQ(calls, 3 * 2);                   // ceil(70/32) x ceil(40/32) blocks
    EXPECT_EQ(reportedTotal, 70u * 40u * 2u);  // samples, not blocks: the ETA follows work done
    EXPECT_EQ(last, reportedTotal);
    EXPECT_EQ(stats.counters.camera.rays, 70u * 40u * 2u);
    EXPECT_EQ(stats.objects, s.primitives.size());
    EXPECT_EQ(stats.lights, 2u);
}
