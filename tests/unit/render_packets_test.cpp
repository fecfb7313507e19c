// rt-render's camera rays as packets (Tracer::pixelRun, --packets) give the picture and the
// counters of the one-by-one path, bit for bit, on SSE2, AVX2 and AVX-512 lanes, for any thread
// count and region split; the thesis scenes through the KD tree. (Models with textures, cut-outs
// and single-sided surfaces: tests/cli/render_packets.sh.)
#include <gtest/gtest.h>

#include <cstring>

#include "accel/build.h"
#include "packet_lanes.h"
#include "render/renderer.h"
#include "render/tracer.h"
#include "scene/thesis_scenes.h"

using namespace rt;

namespace {

bool sameBits(const Framebuffer& a, const Framebuffer& b) {
    return a.pixels().size() == b.pixels().size() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Color)) == 0 &&
           a.alphas() == b.alphas();
}

// Shadows and reflections on, a size off the block grid and off the packets' width.
RenderSettings picture(bool packets, int threads) {
    RenderSettings r;
    r.width = 77;
    r.height = 45;
    r.shadows = true;
    r.reflectionDepth = 3;
    r.packets = packets;
    r.threads = threads;
    return r;
}

class RenderPackets : public test::PacketLanes {};

}  // namespace

TEST_P(RenderPackets, ThesisScenesAreTheSameBitsAndCountsAsSingleRays) {
    for (const auto name : {"balls", "ships", "tree", "pyramid5"}) {
        SCOPED_TRACE(name);
        const Scene scene = thesisScene(name);
        const std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, {});
        RenderStats single, packets;
        const Framebuffer reference = render(scene, *accel, picture(false, 1), single);
        const Framebuffer traced = render(scene, *accel, picture(true, 2), packets);
        EXPECT_TRUE(sameBits(traced, reference));
        EXPECT_EQ(packets.counters.rays(), single.counters.rays());
        EXPECT_EQ(packets.counters.camera.traversalSteps, single.counters.camera.traversalSteps);
        EXPECT_EQ(packets.counters.total().intersectionTests, single.counters.total().intersectionTests);
    }
}

// Regions start their packets at other pixels; each pixel's bits stay.
TEST_P(RenderPackets, RegionsEqualTheFullRender) {
    const Scene scene = thesisScene("ships");
    const std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, {});
    RenderSettings settings = picture(true, 2);
    RenderStats stats;
    const Framebuffer full = render(scene, *accel, picture(false, 2), stats);
    for (const PixelWindow& w : {PixelWindow{0, 0, 35, 20}, PixelWindow{35, 0, 77, 20}, PixelWindow{3, 20, 77, 45}}) {
        settings.region = w;
        const Framebuffer tile = render(scene, *accel, settings, stats);
        for (int y = w.y0; y < w.y1; ++y)
            for (int x = w.x0; x < w.x1; ++x)
                ASSERT_EQ(std::memcmp(&tile.at(x, y), &full.at(x, y), sizeof(Color)), 0) << x << "," << y;
    }
}

// Only renders whose pixels are one camera ray through the centre, without AOVs, take packets.
TEST_P(RenderPackets, OnlyOneSampleRendersWithoutAovsTakePackets) {
    const Scene scene = thesisScene("ships");
    const std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, {});
    RenderSettings s = picture(true, 1);
    EXPECT_TRUE(Tracer(scene, *accel, s).tracesPackets());
    s.packets = false;
    EXPECT_FALSE(Tracer(scene, *accel, s).tracesPackets());
    s = picture(true, 1);
    s.pixelSamples = 4;
    EXPECT_FALSE(Tracer(scene, *accel, s).tracesPackets());
    s = picture(true, 1);
    s.aovs = {Aov::Cost};
    EXPECT_FALSE(Tracer(scene, *accel, s).tracesPackets());
}

INSTANTIATE_PACKET_LANES(RenderPackets);
