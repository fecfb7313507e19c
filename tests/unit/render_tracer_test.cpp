#include "render/integrators/tracer.h"

#include <climits>

#include "accel/naive.h"
#include "core/error.h"
#include "render/materials/phong.h"
#include "render/renderer.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// One white diffuse sphere at the origin seen from -z, one light at the camera.
Scene litWhiteSphere() {
    return test::litSphereSeenFromMinusZ(
        {.name = "white", .color = {0.5f, 1.0f, 0.25f}, .phong = {.ambient = 0.2f, .diffuse = 0.6f}}, 30,
        {{{0, 0, -10}, {0.5f, 0.5f, 0.5f}, 0}, {{0, 0, 10}, {0.25f, 0.25f, 0.25f}, 0}});  // behind: ambient only
}

}  // namespace

TEST(Tracer, MissesShowTheBackground) {
    const Scene s = litWhiteSphere();
    const NaiveAccelerator accel(s.primitives);
    const Tracer tracer(s, accel, test::picture(64, 64));
    RenderCounters c;
    EXPECT_EQ(tracer.pixel(0, 0, c), s.background);
    EXPECT_EQ(c.camera.rays, 1u);
    EXPECT_EQ(c.shadow.rays, 0u);
}

TEST(Tracer, CentreOfALitSphereIsAmbientPlusLambert) {
    const Scene s = litWhiteSphere();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = test::picture(64, 64);
    settings.shadows = true;
    const Tracer tracer(s, accel, settings);
    RenderCounters c;
    // The light is at the camera, so at the centre L.N = 1. The ambient light is the sum
    // of both lights (0.75); the second light is behind the surface and sends no shadow ray.
    const Color got = tracer.pixel(31, 31, c);
    const Material& m = s.materials[0];
    const float cosine = float(dot(normalize(Vec3{0, 0, -10} - Vec3{0, 0, -1}), Vec3{0, 0, -1}));
    const Color want = m.color * (0.75f * m.phong.ambient) + m.color * (0.5f * m.phong.diffuse * cosine);
    EXPECT_NEAR(got.r, want.r, 2e-3);
    EXPECT_NEAR(got.g, want.g, 2e-3);
    EXPECT_NEAR(got.b, want.b, 2e-3);
    EXPECT_EQ(c.shadow.rays, 1u);
}

TEST(Tracer, ShadowsDarkenTheFloorUnderASphere) {
    Scene s;
    test::addMaterial(s, {.name = "grey", .color = {1, 1, 1}, .phong = {.ambient = 0.1f, .diffuse = 0.9f}});
    test::addQuad(s, {-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, 0);
    s.looseObjects.add<Sphere>({{0, 5, 0}, 1}, 0);
    s.lights.push_back({{0, 8, 0}, {1, 1, 1}, 0});
    s.flatten();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = test::picture(8, 8);
    const Tracer unshadowed(s, accel, settings);
    settings.shadows = true;
    const Tracer shadowed(s, accel, settings);
    RenderCounters c;
    // Rays straight down onto the floor below the sphere: (0.5, 0, 0) sees the light through
    // the sphere, (4, 0, 0) past it.
    const auto down = [](Real x) { return Ray{{x, 0.5, 0}, {0, -1, 0}}; };
    SampleRng rng{0, 0, 0};
    const Color lit = unshadowed.trace(down(0.5), 0, false, rng, c);
    const Color dark = shadowed.trace(down(0.5), 0, false, rng, c);
    EXPECT_GT(lit.r, 0.9f);
    EXPECT_NEAR(dark.r, 0.1f, 1e-6);  // ambient only: k_a times the one light
    EXPECT_EQ(shadowed.trace(down(4), 0, false, rng, c), unshadowed.trace(down(4), 0, false, rng, c));
    EXPECT_EQ(c.shadow.rays, 2u);
}

TEST(Tracer, SoftShadowsGiveAPenumbra) {
    // A sphere of radius 1 at height 5 under a light of radius 1 at height 8: the floor point
    // at x = 8/3 sees the light's centre just past the sphere's edge, so about half the light.
    Scene s;
    test::addMaterial(s, {.name = "grey", .color = {1, 1, 1}, .phong = {.ambient = 0, .diffuse = 1}});
    test::addQuad(s, {-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, 0);
    s.looseObjects.add<Sphere>({{0, 5, 0}, 1}, 0);
    s.lights.push_back({{0, 8, 0}, {1, 1, 1}, 1});
    s.flatten();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = test::picture(8, 8);
    settings.shadows = true;
    const Ray down{{Real(8) / 3, 0.5, 0}, {0, -1, 0}};
    SampleRng rng{0, 0, 0};
    RenderCounters c;
    const Color hard = Tracer(s, accel, settings).trace(down, 0, false, rng, c);
    settings.softShadows = true;
    settings.distributedSamples = 256;
    const Color soft = Tracer(s, accel, settings).trace(down, 0, false, rng, c);
    settings.shadows = false;
    const Color lit = Tracer(s, accel, settings).trace(down, 0, false, rng, c);
    EXPECT_GT(soft.r, 0.25f * lit.r);
    EXPECT_LT(soft.r, 0.75f * lit.r);
    EXPECT_EQ(c.shadow.rays, 1u + 256u);
    EXPECT_TRUE(hard.r == 0 || hard.r == lit.r);  // a point light is all or nothing
}

TEST(Tracer, GlossyReflectionsSpreadAroundTheMirrorDirection) {
    // The test scene's blue sphere has a spread: with it, its reflections become bundles of -r
    // rays; with spread 0 every material is a plain mirror with one ray per bounce.
    const Scene s = test::spheresOnFloor();
    Scene sharpScene = s;
    for (Material& m : sharpScene.materials) m.phong.spread = 0;
    const NaiveAccelerator accel(s.primitives);  // the same geometry serves both
    RenderSettings settings = test::picture(64, 48);
    settings.reflectionDepth = 2;
    settings.glossyReflections = true;
    settings.distributedSamples = 16;
    const Tracer tracer(s, accel, settings);
    const Tracer mirrors(sharpScene, accel, settings);
    RenderCounters glossy, sharp;
    for (int x = 0; x < 64; ++x) {  // a row across the blue sphere and the floor
        tracer.pixel(x, 30, glossy);
        mirrors.pixel(x, 30, sharp);
    }
    EXPECT_GT(glossy.reflection.rays, sharp.reflection.rays);
    EXPECT_LE(sharp.reflection.rays, 64u * 2u);  // at most one reflection ray per bounce
}

TEST(Tracer, ReflectionsStopAtTheMaximumDepth) {
    // Two facing mirrors with the camera between them, looking at one: every camera ray
    // bounces between them until the depth limit.
    Scene s;
    s.camera.origin = {0, 0, 0};
    s.camera.destination = {0, 0, 1};
    s.camera.fovDegrees = 10;
    test::addMaterial(s, {.name = "mirror", .phong = {.reflection = 0.5f}});
    test::addQuad(s, {-50, -50, 5}, {50, -50, 5}, {50, 50, 5}, {-50, 50, 5}, 0);
    test::addQuad(s, {-50, -50, -5}, {-50, 50, -5}, {50, 50, -5}, {50, -50, -5}, 0);
    s.flatten();
    const NaiveAccelerator accel(s.primitives);
    for (int depth : {1, 3, 10}) {
        RenderSettings settings = test::picture(8, 6);
        settings.reflectionDepth = depth;
        RenderStats stats;
        render(s, accel, settings, stats);
        EXPECT_EQ(stats.counters.camera.rays, 48u);
        EXPECT_EQ(stats.counters.reflection.rays, 48u * std::uint64_t(depth)) << "depth " << depth;
        EXPECT_EQ(stats.counters.total().intersectionTests, 4u * stats.counters.rays());  // naive: 4 triangles per ray
    }
}

TEST(Tracer, EpsilonScalesWithTheScene) {
    Scene a = litWhiteSphere();
    Scene b = litWhiteSphere();
    b.looseObjects.add<Sphere>({{1000, 0, 0}, 1}, 0);
    b.flatten();
    const NaiveAccelerator accelA(a.primitives), accelB(b.primitives);
    const Tracer ta(a, accelA, test::picture(4, 4)), tb(b, accelB, test::picture(4, 4));
    EXPECT_GT(ta.epsilon(), 0);
    EXPECT_GT(tb.epsilon(), 100 * ta.epsilon());
}

TEST(Phong, HighlightPeaksAtTheMirrorDirection) {
    const Material m{.name = "shiny", .color = {1, 1, 1}, .phong = {.diffuse = 0, .specular = 1, .shininess = 10}};
    const Vec3 n{0, 1, 0};
    const Vec3 toLight = normalize(Vec3{1, 1, 0});
    const Color peak = phongLight(m, m.color, n, toLight, normalize(Vec3{-1, 1, 0}), {1, 1, 1});
    const Color off = phongLight(m, m.color, n, toLight, normalize(Vec3{-1, 2, 0}), {1, 1, 1});
    EXPECT_NEAR(peak.r, 1.0f, 1e-5);
    EXPECT_LT(off.r, 0.9f);
    EXPECT_EQ(phongLight(m, m.color, n, normalize(Vec3{1, -1, 0}), n, {1, 1, 1}), Color{});  // light below the surface
    expectNear(mirror(normalize(Vec3{1, -1, 0}), n), normalize(Vec3{1, 1, 0}));
}

TEST(RenderSettings, OutOfRangeSettingsAreInputErrors) {
    const auto bad = [](auto change) {
        RenderSettings s;
        change(s);
        EXPECT_THROW(validate(s), InputError);
    };
    bad([](RenderSettings& s) { s.width = 0; });
    bad([](RenderSettings& s) { s.height = kMaxImageSide + 1; });
    bad([](RenderSettings& s) { s.reflectionDepth = kMaxReflectionDepth + 1; });
    bad([](RenderSettings& s) { s.distributedSamples = kMaxSamples + 1; });
    bad([](RenderSettings& s) { s.reflectionDepth = -1; });
    bad([](RenderSettings& s) { s.pixelSamples = 0; });
    bad([](RenderSettings& s) { s.width = s.height = 65536; });  // 48 GB of framebuffer
    bad([](RenderSettings& s) { s.region = PixelWindow{10, 10, 10, 20}; });
    bad([](RenderSettings& s) { s.region = PixelWindow{0, 0, 801, 600}; });
    // Its width does not fit in an int: no signed overflow (UBSan) before the region is refused.
    bad([](RenderSettings& s) { s.region = PixelWindow{INT_MIN, 0, INT_MAX, 600}; });
    RenderSettings ok;
    ok.region = PixelWindow{0, 0, 800, 600};
    EXPECT_NO_THROW(validate(ok));
    // The limits the tools' options check are the ones validate() accepts.
    ok.reflectionDepth = kMaxReflectionDepth;
    ok.pixelSamples = ok.distributedSamples = kMaxSamples;
    EXPECT_NO_THROW(validate(ok));
    ok.width = ok.height = 65536;
    ok.region = PixelWindow{0, 0, 4096, 4096};  // a tile of a huge image is fine
    EXPECT_NO_THROW(validate(ok));
}
