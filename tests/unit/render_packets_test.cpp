// rt-render's camera rays and their shadow rays as packets (Tracer::pixelRun, --packets) give the
// picture and the counters of the one-by-one path, bit for bit, on SSE2, AVX2 and AVX-512 lanes,
// for any thread count and region split; the thesis scenes through the KD tree, and point, spot
// and directional lights, hard and soft shadows, with and without glass, through both trees.
// (Models with textures, cut-outs and single-sided surfaces: tests/cli/render_packets.sh.)
#include <gtest/gtest.h>

#include <cstring>

#include "accel/build.h"
#include "render/integrators/tracer.h"
#include "render/renderer.h"
#include "render_test_scenes.h"
#include "scene/thesis_scenes.h"
#include "simd_lanes.h"

using namespace rt;

namespace {

bool sameImage(const Framebuffer& a, const Framebuffer& b) {
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

// Every counter of the two renders is the same.
void expectSameCounters(const RenderCounters& packets, const RenderCounters& single) {
    const auto expectSame = [](const RayCounters& a, const RayCounters& b, const char* kind) {
        EXPECT_EQ(a.rays, b.rays) << kind;
        EXPECT_EQ(a.traversalSteps, b.traversalSteps) << kind;
        EXPECT_EQ(a.intersectionTests, b.intersectionTests) << kind;
    };
    expectSame(packets.camera, single.camera, "camera");
    expectSame(packets.shadow, single.shadow, "shadow");
    expectSame(packets.reflection, single.reflection, "reflection");
}

// Spheres on a floor and a field of small triangles (leaves of triangle blocks) under a point, a
// spot, a directional light and a point light with a size (soft shadows sample it pixel by
// pixel); with `glass`, the mirror sphere is glass, whose shadow rays walk through it per pixel.
Scene shadowedScene(bool glass) {
    Scene s = test::floorAndLights();
    s.lights[1].size = 0;
    s.lights.push_back({.position = {1, 5, -3},
                        .color = {0.4f, 0.3f, 0.3f},
                        .type = Light::Type::Spot,
                        .direction = normalize(Vec3{-0.2, -1, 0.5}),
                        .outerConeDegrees = 35});
    s.lights.push_back({.position = {},
                        .color = {0.2f, 0.2f, 0.25f},
                        .type = Light::Type::Directional,
                        .direction = normalize(Vec3{0.3, -1, 0.6})});
    if (glass) s.materials[2].transmission.weight = 0.8f;
    s.looseObjects.add<Sphere>({{-1.8, 0.8, 0.5}, 0.8}, 1);
    s.looseObjects.add<Sphere>({{0.2, 1.1, 1.2}, 1.1}, 2);
    for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 6; ++j) {
            const Vec3 c{Real(i) * Real(0.35) - 2, Real(0.3) + Real(j) * Real(0.3),
                         Real(-1.5) + Real(i % 3) * Real(0.1)};
            s.looseObjects.add<Triangle>({c, c + Vec3{0.3, 0.05, 0}, c + Vec3{0.1, 0.25, 0.1}}, 3);
        }
    s.flatten();
    return s;
}

class RenderPackets : public test::SimdLanes {};

}  // namespace

TEST_P(RenderPackets, ThesisScenesAreTheSameBitsAndCountsAsSingleRays) {
    for (const auto name : {"balls", "ships", "tree", "pyramid5"}) {
        SCOPED_TRACE(name);
        const Scene scene = thesisScene(name);
        const std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, {});
        RenderStats single, packets;
        const Framebuffer reference = render(scene, *accel, picture(false, 1), single);
        const Framebuffer traced = render(scene, *accel, picture(true, 2), packets);
        EXPECT_TRUE(sameImage(traced, reference));
        expectSameCounters(packets.counters, single.counters);
    }
}

// Shadow rays of every kind of light, as packets where the light takes one ray per pixel and the
// scene has no glass: the same bits and counters, with hard and soft shadows, through both trees.
TEST_P(RenderPackets, ShadowsOfEveryLightAreTheSameBitsAndCountsAsSingleRays) {
    for (const bool glass : {false, true}) {
        const Scene scene = shadowedScene(glass);
        for (const AccelKind kind : {AccelKind::Kd, AccelKind::Bsp}) {
            AccelSettings accelSettings;
            accelSettings.kind = kind;
            const std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, accelSettings);
            for (const bool soft : {false, true}) {
                SCOPED_TRACE(testing::Message()
                             << "glass " << glass << ", " << accel->stats().name << ", soft " << soft);
                RenderSettings off = picture(false, 1), on = picture(true, 2);
                off.softShadows = on.softShadows = soft;
                off.distributedSamples = on.distributedSamples = 8;
                RenderStats single, packets;
                const Framebuffer reference = render(scene, *accel, off, single);
                const Framebuffer traced = render(scene, *accel, on, packets);
                EXPECT_TRUE(sameImage(traced, reference));
                expectSameCounters(packets.counters, single.counters);
                EXPECT_GT(single.counters.shadow.rays, 0u);
            }
        }
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

INSTANTIATE_SIMD_LANES(RenderPackets);
