// The rays rt-inspect --rays counts: camera, shadow and reflection rays, and the work of each.
#include <omp.h>

#include "accel/naive.h"
#include "core/error.h"
#include "inspect/ray_statistics.h"
#include "inspect_test_scenes.h"
#include "render/camera_rays.h"
#include "test_util.h"

using namespace rt;

namespace {

// Pixels whose camera ray hits anything, counted directly.
std::uint64_t cameraHits(const Scene& scene, const Accelerator& accel, const RenderSettings& o) {
    const CameraRays camera(scene.camera, o.width, o.height);
    std::uint64_t hits = 0;
    RayCounters unused;
    for (int y = 0; y < o.height; ++y) {
        for (int x = 0; x < o.width; ++x) {
            Hit hit;
            hits += accel.intersect(camera.at(x + Real(0.5), y + Real(0.5)), kInfinity, hit, unused);
        }
    }
    return hits;
}

}  // namespace

TEST(RayStatistics, CameraRaysOnly) {
    Scene scene = sceneLookingDownZ();
    scene.looseObjects.add<Sphere>({{0, 0, 5}, 1}, 0);
    scene.looseObjects.add<Sphere>({{1, 0, 9}, 1}, 0);
    scene.flatten();
    const NaiveAccelerator naive(scene.primitives);
    RenderSettings options;
    options.width = 20;
    options.height = 10;
    const RenderCounters s = traceRayStatistics(scene, naive, options);
    EXPECT_EQ(s.camera.rays, 200u);
    EXPECT_EQ(s.camera.intersectionTests, 400u);  // the naive list tests both spheres
    EXPECT_EQ(s.shadow.rays, 0u);
    EXPECT_EQ(s.reflection.rays, 0u);
    EXPECT_EQ(testsPerRay(s.total()), 2.0);
}

TEST(RayStatistics, OneShadowRayPerHitAndLightInFront) {
    Scene scene = sceneLookingDownZ();
    scene.looseObjects.add<Sphere>({{0, 0, 5}, 1}, 0);
    scene.lights.push_back({{0, 0, 0}});    // at the camera: in front of every visible point
    scene.lights.push_back({{0, 0, 100}});  // behind the sphere: in front of no visible point
    scene.flatten();
    const NaiveAccelerator naive(scene.primitives);
    RenderSettings options;
    options.width = 32;
    options.height = 24;
    options.shadows = true;
    const RenderCounters s = traceRayStatistics(scene, naive, options);
    const std::uint64_t hits = cameraHits(scene, naive, options);
    ASSERT_GT(hits, 0u);
    ASSERT_LT(hits, 32u * 24u);
    EXPECT_EQ(s.shadow.rays, hits);
    EXPECT_EQ(s.shadow.intersectionTests, hits);  // nothing occludes: one test each
}

TEST(RayStatistics, ReflectionsBounceUpToTheDepth) {
    // Two mirrors facing each other, the camera between them: every camera ray bounces
    // back and forth until the depth limit.
    Scene scene = sceneLookingDownZ();
    scene.camera.fovDegrees = 10;
    Material mirror;
    mirror.phong.reflection = 0.8f;
    scene.materials = {mirror};
    const Real s = 1000;
    for (const Real z : {Real(5), Real(-5)}) {
        scene.looseObjects.add<Triangle>({{-s, -s, z}, {s, -s, z}, {0, s, z}}, 0);
    }
    scene.flatten();
    const NaiveAccelerator naive(scene.primitives);
    RenderSettings options;
    options.width = 8;
    options.height = 6;
    for (const int depth : {0, 1, 3}) {
        options.reflectionDepth = depth;
        const RenderCounters st = traceRayStatistics(scene, naive, options);
        EXPECT_EQ(st.camera.rays, 48u);
        EXPECT_EQ(st.reflection.rays, 48u * depth) << "depth " << depth;
        EXPECT_EQ(st.total().intersectionTests, 2 * st.total().rays);
    }
}

TEST(RayStatistics, MatteSurfacesDoNotReflect) {
    Scene scene = sceneLookingDownZ();
    scene.looseObjects.add<Sphere>({{0, 0, 5}, 1}, 0);
    scene.flatten();
    const NaiveAccelerator naive(scene.primitives);
    RenderSettings options;
    options.width = 8;
    options.height = 6;
    options.reflectionDepth = 5;
    EXPECT_EQ(traceRayStatistics(scene, naive, options).reflection.rays, 0u);
}

TEST(RayStatistics, SameCountsWithOneOrTwoThreads) {
    Scene scene = sceneLookingDownZ();
    Material mirror;
    mirror.phong.reflection = 0.5f;
    scene.materials = {mirror};
    for (int i = 0; i < 5; ++i) scene.looseObjects.add<Sphere>({{Real(i) - 2, 0, 6}, Real(0.6)}, 0);
    scene.lights.push_back({{3, 3, 0}});
    scene.flatten();
    const NaiveAccelerator naive(scene.primitives);
    RenderSettings options;
    options.width = 40;
    options.height = 30;
    options.shadows = true;
    options.reflectionDepth = 3;
    omp_set_num_threads(1);
    const RenderCounters one = traceRayStatistics(scene, naive, options);
    omp_set_num_threads(2);
    const RenderCounters two = traceRayStatistics(scene, naive, options);
    EXPECT_EQ(one.total().rays, two.total().rays);
    EXPECT_EQ(one.total().intersectionTests, two.total().intersectionTests);
    EXPECT_EQ(one.reflection.rays, two.reflection.rays);
    EXPECT_GT(one.reflection.rays, 0u);
}

TEST(RayStatistics, CameraRayWorkPerPixel) {
    Scene scene = sceneLookingDownZ();
    for (int i = 0; i < 3; ++i) scene.looseObjects.add<Sphere>({{0, 0, Real(5 + 3 * i)}, 1}, 0);
    scene.lights.push_back({{0, 0, 0}});
    scene.flatten();
    const NaiveAccelerator naive(scene.primitives);
    RenderSettings picture;
    picture.width = 10;
    picture.height = 8;
    picture.shadows = true;  // not counted: camera rays only
    const std::vector<float> cost = pixelWork(scene, naive, picture, PixelRays::Camera);
    ASSERT_EQ(cost.size(), 80u);
    for (const float c : cost) EXPECT_EQ(c, 3.0f);  // the naive list: every primitive, no traversal
    picture.pixelSamples = 4;
    for (const float c : pixelWork(scene, naive, picture, PixelRays::Camera)) EXPECT_EQ(c, 12.0f);
}

// All rays: a pixel that sees a sphere lit from the camera adds a shadow ray's tests
// (up to 3 with the naive list, fewer when it stops at the first occluder); the rest
// of the picture stays at its camera ray's 3.
TEST(RayStatistics, AllRaysWorkPerPixelAddsShadowRays) {
    Scene scene = sceneLookingDownZ();
    for (int i = 0; i < 3; ++i) scene.looseObjects.add<Sphere>({{0, 0, Real(5 + 3 * i)}, 1}, 0);
    scene.lights.push_back({{0, 0, 0}});
    scene.flatten();
    const NaiveAccelerator naive(scene.primitives);
    RenderSettings picture;
    picture.width = 40;
    picture.height = 30;
    picture.shadows = true;
    const std::vector<float> camera = pixelWork(scene, naive, picture, PixelRays::Camera);
    const std::vector<float> all = pixelWork(scene, naive, picture, PixelRays::All);
    std::size_t lit = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        EXPECT_GE(all[i], camera[i]);
        EXPECT_LE(all[i], camera[i] + 3.0f);
        lit += all[i] > camera[i];
    }
    EXPECT_GT(lit, 0u);
    EXPECT_LT(lit, all.size());
    double sum = 0;
    for (const float w : all) sum += w;
    const RenderCounters counts = traceRayStatistics(scene, naive, picture);
    EXPECT_EQ(sum, double(counts.total().intersectionTests + counts.total().traversalSteps));
}

TEST(RayStatistics, BadCameraIsAnInputError) {
    Scene scene = sceneLookingDownZ();
    scene.camera.destination = scene.camera.origin;
    scene.flatten();
    const NaiveAccelerator naive(scene.primitives);
    EXPECT_THROW(traceRayStatistics(scene, naive, {}), InputError);
}
