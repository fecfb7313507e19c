// Alpha: each pixel's coverage, the fraction of its camera rays that hit something.
#include "accel/naive.h"
#include "render/camera_rays.h"
#include "render/renderer.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

Scene litSphere() { return test::litSphereSeenFromMinusZ({.name = "white"}, 20, {{{-5, 5, -10}, {1, 1, 1}, 0}}); }

}  // namespace

TEST(RenderAlpha, ZeroExactlyWhereTheNaiveTracerFindsNoHit) {
    const Scene s = litSphere();
    const NaiveAccelerator accel(s.primitives);
    const RenderSettings settings = test::picture(48, 36);
    const Framebuffer image = test::renderNaive(s, settings).image;
    const CameraRays camera(s.camera, settings.width, settings.height);
    int misses = 0;
    for (int y = 0; y < settings.height; ++y)
        for (int x = 0; x < settings.width; ++x) {
            Hit hit;
            RayCounters work;
            const bool seen =
                accel.intersect(camera.at(Real(x) + Real(0.5), Real(y) + Real(0.5)), kInfinity, hit, work);
            misses += !seen;
            ASSERT_EQ(image.alphaAt(x, y), seen ? 1.0f : 0.0f) << x << "," << y;
            const std::size_t i = std::size_t(y) * std::size_t(settings.width) + std::size_t(x);
            EXPECT_EQ(image.premultiplied(i), seen ? image.at(x, y) : Color()) << "the background is taken out";
        }
    EXPECT_GT(misses, 0);
    EXPECT_LT(misses, settings.width * settings.height);
}

TEST(RenderAlpha, SupersamplingGivesFractionalCoverageAtTheSilhouette) {
    const Scene s = litSphere();
    RenderSettings settings = test::picture(48, 36);
    settings.pixelSamples = 4;
    const Framebuffer image = test::renderNaive(s, settings).image;
    int partial = 0;
    for (std::size_t i = 0; i < image.alphas().size(); ++i) {
        const float a = image.alphas()[i];
        ASSERT_TRUE(a == 0 || a == 0.25f || a == 0.5f || a == 0.75f || a == 1) << a;
        if (a == 0 || a == 1) continue;
        ++partial;
        // The colour is the hits' mean over the background's share: premultiplied takes that share out.
        const Color over = image.premultiplied(i) + s.background * (1 - a);
        EXPECT_NEAR(over.r, image.pixels()[i].r, 1e-6f);
        EXPECT_NEAR(over.b, image.pixels()[i].b, 1e-6f);
    }
    EXPECT_GT(partial, 10) << "the sphere's edge crosses many pixels";
}
