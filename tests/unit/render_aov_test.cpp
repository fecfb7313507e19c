// AOVs: what each pixel's camera rays found, checked against values computed by hand and
// against rt-inspect's per-pixel work.
#include "render/aov.h"

#include <cmath>

#include "accel/build.h"
#include "accel/naive.h"
#include "core/error.h"
#include "inspect/ray_statistics.h"
#include "render/camera_rays.h"
#include "render/renderer.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// A large square at z = 5, facing the camera at the origin that looks along +z.
Scene planeAtFive() {
    Scene s;
    s.camera.fovDegrees = 90;
    const auto grey = test::addMaterial(s, {.name = "grey", .color = {0.2f, 0.4f, 0.6f}});
    test::addQuad(s, {-100, -100, 5}, {100, -100, 5}, {100, 100, 5}, {-100, 100, 5}, grey);
    s.flatten();
    return s;
}

Framebuffer renderAovs(const Scene& s, const Accelerator& accel, RenderSettings settings) {
    settings.aovs = true;
    RenderStats stats;
    return render(s, accel, settings, stats);
}

}  // namespace

TEST(RenderAov, PlaneAtAKnownDistance) {
    const Scene s = planeAtFive();
    const NaiveAccelerator accel(s.primitives);
    const RenderSettings settings = test::picture(8, 6);
    const Framebuffer image = renderAovs(s, accel, settings);
    const CameraRays camera(s.camera, 8, 6);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            const PixelAovs& a = image.aovs()[std::size_t(y * 8 + x)];
            const Vec3 d = camera.at(Real(x) + Real(0.5), Real(y) + Real(0.5)).direction;
            const Real t = 5 / d.z;  // the ray reaches z = 5 after 5 / d.z
            EXPECT_NEAR(a.z, t, 1e-5) << x << "," << y;
            EXPECT_NEAR(a.p[0], d.x * t, 1e-5);
            EXPECT_NEAR(a.p[1], d.y * t, 1e-5);
            EXPECT_NEAR(a.p[2], 5, 1e-5);
            EXPECT_EQ(a.n[2], -1) << "the shading normal faces the camera";
            EXPECT_EQ(std::abs(a.ng[2]), 1);
            EXPECT_EQ(a.albedo, Color(0.2f, 0.4f, 0.6f));
            EXPECT_EQ(a.material, 0u);
            EXPECT_LT(a.primitive, 2u);
        }
}

TEST(RenderAov, MissesHaveInfiniteDepthAndNoIds) {
    Scene s = planeAtFive();
    s.camera.destination = {0, 0, -1};  // looking away from the plane
    const NaiveAccelerator accel(s.primitives);
    const Framebuffer image = renderAovs(s, accel, test::picture(4, 3));
    for (const PixelAovs& a : image.aovs()) {
        EXPECT_TRUE(std::isinf(a.z));
        EXPECT_EQ(a.material, kNoId);
        EXPECT_EQ(a.primitive, kNoId);
        EXPECT_EQ(a.albedo, Color());
    }
}

// The cost layer is rt-inspect's heat map as data: the same work per pixel, for the camera
// rays alone and for every ray they spawn.
TEST(RenderAov, CostEqualsRtInspectsPixelWork) {
    const Scene s = test::spheresOnFloor();
    const std::unique_ptr<Accelerator> kd = buildAccelerator(s.primitives, AccelSettings{});
    RenderSettings settings = test::picture(40, 30);
    settings.shadows = true;
    settings.reflectionDepth = 3;
    const Framebuffer image = renderAovs(s, *kd, settings);
    const std::vector<float> camera = pixelWork(s, *kd, settings, PixelRays::Camera);
    const std::vector<float> all = pixelWork(s, *kd, settings, PixelRays::All);
    float most = 0;
    for (std::size_t i = 0; i < camera.size(); ++i) {
        const PixelAovs& a = image.aovs()[i];
        ASSERT_EQ(a.steps + a.tests, camera[i]) << i;
        ASSERT_EQ(a.allSteps + a.allTests, all[i]) << i;
        most = std::max(most, a.allTests);
    }
    EXPECT_GT(most, 0);
}

TEST(RenderAov, SupersamplingAveragesAndTakesIdsFromTheFirstSample) {
    const Scene s = planeAtFive();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = test::picture(8, 6);
    settings.pixelSamples = 4;
    const Framebuffer image = renderAovs(s, accel, settings);
    const PixelAovs& corner = image.aovs()[0];
    const CameraRays camera(s.camera, 8, 6);
    // The mean of four distances inside the corner pixel lies between its corners' distances.
    const Real near = 5 / camera.at(1, 1).direction.z, far = 5 / camera.at(0, 0).direction.z;
    EXPECT_GT(corner.z, near);
    EXPECT_LT(corner.z, far);
    EXPECT_EQ(corner.steps, 0);  // the naive list has no nodes
    EXPECT_EQ(corner.tests, 2);  // two triangles per camera ray, averaged over the four
}

TEST(RenderAov, ListsByName) {
    EXPECT_EQ(parseAovList("cost,Z"), (std::vector<Aov>{Aov::Z, Aov::Cost}));
    EXPECT_EQ(parseAovList("all").size(), aovLayers().size());
    EXPECT_THROW(parseAovList("depth"), InputError);
}
