// AOVs: what each pixel's camera rays found, checked against values computed by hand and
// against rt-inspect's per-pixel work.
#include "render/film/aov.h"

#include <cmath>
#include <cstring>

#include "accel/build.h"
#include "accel/naive.h"
#include "core/error.h"
#include "inspect/ray_statistics.h"
#include "render/camera_rays.h"
#include "render/integrators/path_tracer.h"
#include "render/renderer.h"
#include "render/surface.h"
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
    settings.aovs = parseAovList("all");
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

// The albedo is the colour the shading uses: the material's colour times the vertex colour
// times the texture (here a solid checker of unit cubes) at the hit point.
TEST(RenderAov, AlbedoOfATexturedPlaneHasItsTextureAndVertexColours) {
    Scene s = planeAtFive();
    s.textures.push_back({.name = "checker", .kind = Texture::Kind::Checker, .colorA = {1, 0, 0}, .colorB = {0, 0, 1}});
    s.materials[0].colorTexture = 0;
    CornerColors tint;
    for (int corner = 0; corner < 3; ++corner) tint.values[std::size_t(3 * corner)] = 0.5f;  // (0.5, 1, 1)
    for (std::uint32_t triangle = 0; triangle < 2; ++triangle)
        s.primitives.triangleShading().colors.set(triangle, tint);
    const Framebuffer image = renderAovs(s, NaiveAccelerator(s.primitives), test::picture(8, 6));
    int red = 0, blue = 0;
    for (const PixelAovs& a : image.aovs()) {
        // The plane at z = 5 lies on a cube boundary; the camera sees the cubes behind it (z in 5..6).
        const bool even = (int(std::floor(a.p[0])) + int(std::floor(a.p[1])) + 5) % 2 == 0;
        const Color checker = even ? Color{1, 0, 0} : Color{0, 0, 1};
        const Color want = Color(0.2f * 0.5f, 0.4f, 0.6f) * checker;  // colour x vertex colour x texture
        EXPECT_NEAR(a.albedo.r, want.r, 1e-6f) << a.p[0] << "," << a.p[1];
        EXPECT_NEAR(a.albedo.g, want.g, 1e-6f);
        EXPECT_NEAR(a.albedo.b, want.b, 1e-6f);
        (even ? red : blue) += 1;
    }
    EXPECT_GT(red, 0);
    EXPECT_GT(blue, 0);
}

// N is the shading normal the lighting uses: a mesh's interpolated vertex normals (turned to the
// camera's side), not the facet's normal, which Ng keeps as the primitive defines it.
TEST(RenderAov, NormalOfASmoothMeshIsItsInterpolatedVertexNormal) {
    Scene s = planeAtFive();
    CornerNormals tilted;
    const Vec3 n0{0.6, 0, -0.8}, n1{0, 0.6, -0.8};
    for (int corner = 0; corner < 3; ++corner)
        for (int c = 0; c < 3; ++c) tilted.values[std::size_t(3 * corner + c)] = float(corner == 0 ? n0[c] : n1[c]);
    for (std::uint32_t triangle = 0; triangle < 2; ++triangle)
        s.primitives.triangleShading().normals.set(triangle, tilted);
    const Framebuffer image = renderAovs(s, NaiveAccelerator(s.primitives), test::picture(8, 6));
    for (const PixelAovs& a : image.aovs()) {
        // Each triangle's corner 0 is (-100, -100, 5); the hit's weight of it follows from the point.
        const bool first = a.p[0] >= a.p[1];  // the triangle (a, b, c) below the diagonal, else (a, c, d)
        const Real w0 = first ? (100 - Real(a.p[0])) / 200 : (100 - Real(a.p[1])) / 200;
        // as the shading turns it where it would mirror the view into the plane (render/surface.h)
        const Vec3 p{a.p[0], a.p[1], a.p[2]};
        const Vec3 want =
            keepReflectionAbove(normalize(n0 * w0 + n1 * (1 - w0)), {0, 0, -1}, normalize(s.camera.origin - p));
        EXPECT_NEAR(a.n[0], want.x, 1e-5) << a.p[0] << "," << a.p[1];
        EXPECT_NEAR(a.n[1], want.y, 1e-5);
        EXPECT_NEAR(a.n[2], want.z, 1e-5);
        EXPECT_EQ(std::abs(a.ng[2]), 1) << "the geometric normal stays the facet's";
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

// The path tracer's AOVs are its camera rays' hits, as the Whitted tracer's are: on the plane
// at z = 5 the point lies on the plane at its distance, the normal faces the camera, the
// albedo is the plane's colour, the cost of a camera ray two tests of the naive list (one path
// a pixel, so that the distance is the point's).
TEST(RenderAovPath, PlaneAtAKnownDistance) {
    const Scene s = planeAtFive();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = test::picture(8, 6);
    settings.integrator = Integrator::Path;
    const Framebuffer image = renderAovs(s, accel, settings);
    for (const PixelAovs& a : image.aovs()) {
        EXPECT_NEAR(a.p[2], 5, 1e-5);
        EXPECT_NEAR(a.z, std::sqrt(a.p[0] * a.p[0] + a.p[1] * a.p[1] + 25), 1e-4);
        EXPECT_EQ(a.n[2], -1);
        EXPECT_EQ(std::abs(a.ng[2]), 1);
        EXPECT_EQ(a.albedo, Color(0.2f, 0.4f, 0.6f));
        EXPECT_EQ(a.material, 0u);
        EXPECT_LT(a.primitive, 2u);
        EXPECT_EQ(a.tests, 2);
        EXPECT_GT(a.allTests, a.tests) << "next-event shadow rays and bounces";
    }
}

namespace {}  // namespace

// Every layer has the same bits for one thread or two, in a region, and as PathTracer::pixel
// takes the pixel's samples in one loop (the renderer takes one per pass).
TEST(RenderAovPath, SameBitsForAnyThreadCountRegionAndPasses) {
    const Scene s = test::spheresOnFloor();
    const std::unique_ptr<Accelerator> kd = buildAccelerator(s.primitives, AccelSettings{});
    RenderSettings one = test::picture(40, 30);
    one.integrator = Integrator::Path;
    one.pixelSamples = 3;
    one.threads = 1;
    const Framebuffer whole = renderAovs(s, *kd, one);
    RenderSettings two = one;
    two.threads = 2;
    const Framebuffer parallel = renderAovs(s, *kd, two);
    two.region = PixelWindow{5, 3, 37, 29};
    const Framebuffer region = renderAovs(s, *kd, two);
    RenderSettings withAovs = one;
    withAovs.aovs = parseAovList("all");
    const PathTracer tracer(s, *kd, withAovs);
    int hits = 0;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) {
            const std::size_t i = std::size_t(y * 40 + x);
            ASSERT_TRUE(sameBits(whole.aovs()[i], parallel.aovs()[i])) << x << "," << y;
            if (x >= 5 && x < 37 && y >= 3 && y < 29) {
                ASSERT_TRUE(sameBits(whole.aovs()[i], region.aovs()[std::size_t((y - 3) * 32 + x - 5)]))
                    << x << "," << y;
            }
            RenderCounters counters;
            float coverage;
            PixelAovs inOneLoop;
            tracer.pixel(x, y, counters, coverage, &inOneLoop);
            ASSERT_TRUE(sameBits(whole.aovs()[i], inOneLoop)) << x << "," << y;
            hits += whole.aovs()[i].primitive != kNoId;
        }
    EXPECT_GT(hits, 100);
}
