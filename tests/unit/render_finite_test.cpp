// Rendered pixels are finite and within what the Phong model allows; a sample that comes out
// NaN or infinite anyway is written as black and counted, never passed on silently.
#include <filesystem>
#include <limits>

#include "accel/build.h"
#include "accel/naive.h"
#include "io/xml_loader.h"
#include "render/renderer.h"
#include "render/sampling.h"
#include "render_test_scenes.h"
#include "scene/thesis_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// The largest value the tracer can give one colour channel, from what tracer.cpp computes. A
// hit adds to its ambient term k_a c I_a (I_a: the sum of the lights) each light's
// k_d c (L.N) I + k_s (R.V)^n I, at most (k_d c + k_s) I since L.N, R.V and the visible
// fraction are at most 1, and, below the deepest reflection, its reflection coefficient
// times what the reflected ray sees; a miss sees the background. Averages of samples or
// of a glossy bundle stay below their largest member.
float channelBound(const Scene& s, int reflectionDepth, float Color::*channel) {
    float ambientLight = 0;
    for (const Light& l : s.lights) ambientLight += l.color.*channel;
    std::vector<Material> materials = s.materials;
    materials.push_back(Material{});  // what the tracer uses for a primitive without one
    float seen = 0;                   // what a ray reflected at the current depth sees at most; none below the deepest
    for (int depth = reflectionDepth; depth >= 0; --depth) {
        float deepest = s.background.*channel;
        for (const Material& m : materials) {
            float local = m.phong.ambient * (m.color.*channel) * ambientLight;
            for (const Light& l : s.lights)
                local += (m.phong.diffuse * (m.color.*channel) + m.phong.specular) * (l.color.*channel);
            deepest = std::max(deepest, local + (depth < reflectionDepth ? m.phong.reflection * seen : 0.0f));
        }
        seen = deepest;
    }
    return seen;
}

// Renders with shadows and reflections to `reflectionDepth`, then checks every pixel: finite, not
// negative, within the Phong bound (with room for float rounding), and no sample replaced.
void expectFiniteAndBounded(const Scene& scene, const Accelerator& accel, int width, int height, int reflectionDepth) {
    RenderSettings settings = test::picture(width, height);
    settings.reflectionDepth = reflectionDepth;
    settings.shadows = true;
    RenderStats stats;
    const Framebuffer image = render(scene, accel, settings, stats);
    EXPECT_EQ(stats.counters.nonFinite.count, 0u)
        << "first at pixel (" << stats.counters.nonFinite.firstX << ", " << stats.counters.nonFinite.firstY << ")";
    int reported = 0;
    for (float Color::*channel : {&Color::r, &Color::g, &Color::b}) {
        const float bound = channelBound(scene, reflectionDepth, channel) * 1.0001f;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const float v = image.at(x, y).*channel;
                if (std::isfinite(v) && v >= 0 && v <= bound) continue;
                ADD_FAILURE() << "pixel (" << x << ", " << y << ") = " << image.at(x, y) << ", bound " << bound;
                if (++reported == 5) return;
            }
    }
}

void expectFiniteAndBounded(const Scene& scene, int width, int height, int reflectionDepth) {
    const std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, AccelSettings{});
    expectFiniteAndBounded(scene, *accel, width, height, reflectionDepth);
}

// A lattice of 12^3 small mirror spheres (radius 0.006, as the smallest of the balls scene),
// 0.02 apart and jittered by up to a quarter of that, so that some touch: rays bounce between
// them to the last reflection.
Scene smallReflectiveSphereField() {
    Scene s;
    s.background = {0.1f, 0.1f, 0.2f};
    s.camera.origin = {0.342, 0.246, 0.193};
    s.camera.destination = {0, 0, 0};
    s.camera.up = {0, 0, 1};
    s.camera.fovDegrees = 50;
    const auto chrome = test::addMaterial(
        s, {.name = "chrome",
            .color = {0.9f, 0.8f, 0.6f},
            .phong = {.ambient = 0.05f, .diffuse = 0.5f, .specular = 0.8f, .shininess = 60, .reflection = 0.9f}});
    constexpr int n = 12;
    constexpr Real spacing = Real(0.02), half = spacing * (n - 1) / 2;
    SampleRng random{17, 4, 2026};
    const auto jitter = [&random] { return (random.uniform() - Real(0.5)) * spacing / 2; };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const Vec3 lattice = Vec3{Real(i), Real(j), Real(k)} * spacing - Vec3{half, half, half};
                s.looseObjects.add<Sphere>({lattice + Vec3{jitter(), jitter(), jitter()}, Real(0.006)}, chrome);
            }
    s.lights.push_back({{2, 1, 3}, {0.6f, 0.6f, 0.6f}, 0});
    s.lights.push_back({{-1, 2, 1}, {0.5f, 0.4f, 0.3f}, 0});
    s.flatten();
    return s;
}

// One sphere lit by a light of infinite intensity: every sample that hits the sphere is
// infinite in red and blue and NaN in green (infinity times the colour's zero).
Scene sphereUnderAnInfiniteLight() {
    const float inf = std::numeric_limits<float>::infinity();
    return test::litSphereSeenFromMinusZ(
        {.name = "magenta", .color = {1, 0, 1}, .phong = {.ambient = 0.1f, .diffuse = 0.8f}}, 20,
        {{{0, 5, -10}, {inf, inf, inf}, 0}});
}

bool isBlack(const Color& c) { return c == Color{}; }

}  // namespace

TEST(RenderFinite, BundledScenesStayWithinThePhongBoundAtDepth10) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(RT_SOURCE_DIR "/scenes")) {
        if (entry.path().extension() != ".xml") continue;
        SCOPED_TRACE(entry.path().filename().string());
        expectFiniteAndBounded(loadSceneXml(entry.path().string()), 80, 60, 10);
        ++scenes;
    }
    EXPECT_GE(scenes, 4);
}

TEST(RenderFinite, SmallReflectiveSpheresStayWithinThePhongBoundAtDepth10) {
    expectFiniteAndBounded(smallReflectiveSphereField(), 120, 90, 10);
}

TEST(RenderFinite, BallsSceneIsFiniteAtDepth10) {
    const Scene balls = thesisBalls();  // the thesis's test scene, as rt-convert --generate balls writes it
    ASSERT_EQ(balls.primitives.count<Sphere>(), 7381u);
    expectFiniteAndBounded(balls, 100, 75, 10);
}

TEST(RenderFinite, NonFiniteSamplesAreWrittenAsBlackAndCounted) {
    const Scene s = sphereUnderAnInfiniteLight();
    const RenderSettings settings = test::picture(40, 30);
    const auto [image, stats] = test::renderNaive(s, settings);
    std::uint64_t black = 0;
    int firstX = -1, firstY = -1;
    for (int y = 0; y < settings.height; ++y)
        for (int x = 0; x < settings.width; ++x) {
            const Color& c = image.at(x, y);
            ASSERT_TRUE(isBlack(c) || c == s.background) << "pixel (" << x << ", " << y << ") = " << c;
            if (!isBlack(c) || black++) continue;
            firstX = x;
            firstY = y;
        }
    EXPECT_GT(black, 0u);
    EXPECT_EQ(stats.counters.nonFinite.count, black);  // one sample per pixel
    EXPECT_EQ(stats.counters.nonFinite.firstX, firstX);
    EXPECT_EQ(stats.counters.nonFinite.firstY, firstY);
}

TEST(RenderFinite, TheCountAndTheFirstPixelAreTheSameForAnyThreadsAndRegions) {
    const Scene s = sphereUnderAnInfiniteLight();
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = test::picture(70, 50);
    settings.pixelSamples = 3;
    settings.threads = 1;
    RenderStats one, two;
    render(s, accel, settings, one);
    settings.threads = 2;
    render(s, accel, settings, two);
    EXPECT_EQ(one.counters.nonFinite.count, two.counters.nonFinite.count);
    EXPECT_EQ(one.counters.nonFinite.firstX, two.counters.nonFinite.firstX);
    EXPECT_EQ(one.counters.nonFinite.firstY, two.counters.nonFinite.firstY);
    // Tiles, in reverse order: their statistics add up to the whole picture's.
    NonFiniteSamples tiles;
    for (const PixelWindow& w : {PixelWindow{35, 25, 70, 50}, PixelWindow{0, 25, 35, 50}, PixelWindow{35, 0, 70, 25},
                                 PixelWindow{0, 0, 35, 25}}) {
        settings.region = w;
        RenderStats tile;
        render(s, accel, settings, tile);
        tiles += tile.counters.nonFinite;
    }
    EXPECT_GT(tiles.count, 0u);
    EXPECT_EQ(tiles.count, one.counters.nonFinite.count);
    EXPECT_EQ(tiles.firstX, one.counters.nonFinite.firstX);
    EXPECT_EQ(tiles.firstY, one.counters.nonFinite.firstY);
}
