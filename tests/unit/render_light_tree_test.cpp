// The light tree (render/lights/light_tree.h) and the light distribution that uses it
// (render/lights/light_distribution.h): next-event estimation of the direct light at a point, through
// the tree or in proportion to power, agrees with the sum over every light computed without
// sampling; the tree's choice is noticeably less noisy among many small lights; densities for
// MIS agree with the samples; a diffuse sphere inside an enclosure of emissive triangles shows
// albedo times their radiance; and the same bits for any thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "core/random.h"
#include "render/lights/light_distribution.h"
#include "render/lights/light_sample.h"
#include "render/lights/light_tree.h"
#include "render/sobol_sampler.h"
#include "render_path_util.h"
#include "render_test_scenes.h"

using namespace rt;

namespace {

constexpr Color kLampRadiance{2, 2, 2};

// Small emissive triangles scattered over a 20 x 20 patch above y = 0 and facing every way, with
// inverse-square point and spot lights among them and a thesis point light, no sky.
Scene manyLights() {
    Scene s;
    Material lamp = test::pbr({0, 0, 0}, 0, 1, 0);
    lamp.emission.color = kLampRadiance;
    const auto emissive = test::addMaterial(s, lamp);
    SplitMix64 rng{7};
    const auto uniform = [&](Real lo, Real hi) { return lo + (hi - lo) * Real(rng.next() >> 11) * Real(0x1p-53); };
    for (int i = 0; i < 300; ++i) {
        const Vec3 c{uniform(-10, 10), uniform(0.5, 4), uniform(-10, 10)};
        const Vec3 a{uniform(-0.2, 0.2), uniform(-0.2, 0.2), uniform(-0.2, 0.2)};
        const Vec3 b{uniform(-0.2, 0.2), uniform(-0.2, 0.2), uniform(-0.2, 0.2)};
        s.looseObjects.add<Triangle>({c, c + a, c + b}, emissive);
    }
    for (int i = 0; i < 12; ++i) {
        Light light{{uniform(-10, 10), uniform(0.5, 4), uniform(-10, 10)}, {0.5f, 0.4f, 0.3f}, 0};
        light.falloff = Light::Falloff::InverseSquare;
        if (i % 3 == 0) {
            light.type = Light::Type::Spot;
            light.direction = normalize(Vec3{uniform(-1, 1), -1, uniform(-1, 1)});
            light.innerConeDegrees = 10, light.outerConeDegrees = 40;
        }
        s.lights.push_back(light);
    }
    s.lights.push_back(Light{{0, 50, 0}, {0.01f, 0.01f, 0.01f}, 0});  // everywhere alike: not in the tree
    s.flatten();
    return s;
}

// The irradiance (luminance) light `sample` brings to a point with normal n, shadows left out.
double arriving(const Scene& s, const LightSample& sample, const Vec3& from, const Vec3& n) {
    const Real cosine = dot(sample.direction, n);
    if (!(cosine > 0)) return 0;
    if (sample.source == LightSample::Source::Point)
        return luminance(lightIncidence(s.lights[sample.index], from).color) * double(cosine);
    return luminance(kLampRadiance) * double(cosine);
}

// The same without sampling: the analytic irradiance of each point light, and each triangle
// integrated over a 48 x 48 grid of its area (they are small and far from the points).
double irradiance(const Scene& s, const Vec3& p, const Vec3& n) {
    double sum = 0;
    for (const Light& light : s.lights) {
        const LightIncidence in = lightIncidence(light, p);
        sum += luminance(in.color) * std::max(0.0, double(dot(in.toLight, n)));
    }
    constexpr int kGrid = 48;
    for (const Triangle& tri : s.primitives.all<Triangle>()) {
        double integral = 0;
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j) {
                Real b1 = (i + Real(0.5)) / kGrid, b2 = (j + Real(0.5)) / kGrid;
                if (b1 + b2 > 1) b1 = 1 - b1, b2 = 1 - b2;  // the same fold as the sampler's
                const Vec3 d = tri.p0 + (tri.p1 - tri.p0) * b1 + (tri.p2 - tri.p0) * b2 - p;
                const double r2 = dot(d, d), r = std::sqrt(r2);
                const double atPoint = dot(d, n) / r, atLight = -dot(d, tri.normal()) / r;
                if (atPoint > 0 && atLight > 0) integral += atPoint * atLight / r2;
            }
        sum += luminance(kLampRadiance) * integral * tri.area() / (kGrid * kGrid);
    }
    return sum;
}

struct Estimate {
    double mean = 0, standardError = 0;
};

// Next-event estimation of the irradiance at p from n samples of `lights`.
Estimate estimate(const Scene& s, const LightDistribution& lights, const Vec3& p, const Vec3& n, int samples) {
    SplitMix64 rng{11};
    const auto u = [&] { return Real(rng.next() >> 40) * Real(0x1p-24); };
    double sum = 0, sumSq = 0;
    for (int i = 0; i < samples; ++i) {
        const Real pick = u(), u1 = u(), u2 = u();
        const std::optional<LightSample> light = lights.sample(p, n, pick, u1, u2);
        const double value = light ? arriving(s, *light, p, n) / double(light->pdf) : 0;
        sum += value, sumSq += value * value;
    }
    const double mean = sum / samples;
    return {mean, std::sqrt(std::max(0.0, sumSq / samples - mean * mean) / samples)};
}

// Points on and around the patch, their normals every way (down too: lights below the patch's
// points' own surface light nothing).
struct Place {
    Vec3 point, normal;
};
std::vector<Place> places() {
    return {{{0, 0, 0}, {0, 1, 0}},
            {{5, 1, -3}, normalize(Vec3{1, 1, 0})},
            {{-8, 2, 8}, normalize(Vec3{0, -1, 1})},
            {{12, 0, 12}, normalize(Vec3{-1, 0.2, -1})},
            {{-3, 3, 2}, {0, -1, 0}},
            {{2, 6, 0}, normalize(Vec3{0.3, -1, 0.1})}};
}

}  // namespace

TEST(LightTree, NextEventEstimationAgreesWithTheSumOverEveryLight) {
    const Scene s = manyLights();
    const LightDistribution tree(s, LightSampler::Tree), power(s, LightSampler::Power);
    double treeVariance = 0, powerVariance = 0;
    for (const Place& at : places()) {
        const double expected = irradiance(s, at.point, at.normal);
        const Estimate byTree = estimate(s, tree, at.point, at.normal, 1 << 15);
        const Estimate byPower = estimate(s, power, at.point, at.normal, 1 << 15);
        // within four standard errors, and the grid's own error over small triangles
        EXPECT_NEAR(byTree.mean, expected, 4 * byTree.standardError + 2e-3 * expected) << at.point;
        EXPECT_NEAR(byPower.mean, expected, 4 * byPower.standardError + 2e-3 * expected) << at.point;
        treeVariance += byTree.standardError * byTree.standardError / (expected * expected);
        powerVariance += byPower.standardError * byPower.standardError / (expected * expected);
    }
    // the reason for the tree: the nearby lights that face the point get the samples
    EXPECT_LT(treeVariance, 0.25 * powerVariance);
}

TEST(LightTree, TheDensityForMisIsTheSamplesOwn) {
    const Scene s = manyLights();
    const LightDistribution lights(s, LightSampler::Tree);
    SplitMix64 rng{3};
    const auto u = [&] { return Real(rng.next() >> 40) * Real(0x1p-24); };
    int triangles = 0;
    for (const Place& at : places())
        for (int i = 0; i < 200; ++i) {
            const std::optional<LightSample> light = lights.sample(at.point, at.normal, u(), u(), u());
            if (!light || light->source != LightSample::Source::Triangle) continue;
            ++triangles;
            const Real pdf = lights.pdfTriangle(light->index, at.point, at.normal, light->direction, light->distance);
            ASSERT_NEAR(pdf, light->pdf, 1e-4 * light->pdf) << at.point << " triangle " << light->index;
        }
    EXPECT_GT(triangles, 200);
}

TEST(LightTree, EveryLightThatCanLightAPointKeepsAChance) {
    const Scene s = manyLights();
    std::vector<LightBounds> bounds;
    for (const Triangle& tri : s.primitives.all<Triangle>()) {
        LightBounds b;
        b.box.extend(tri.p0), b.box.extend(tri.p1), b.box.extend(tri.p2);
        b.normals = {tri.normal(), 1};
        b.intensity = tri.area();
        bounds.push_back(b);
    }
    const LightTree tree(bounds);
    const auto triangles = s.primitives.all<Triangle>();
    for (const Place& at : places()) {
        double total = 0;
        for (std::uint32_t i = 0; i < bounds.size(); ++i) {
            const Real p = tree.probability(i, at.point, at.normal);
            total += p;
            const Triangle& tri = triangles[i];
            const Vec3 centre = (tri.p0 + tri.p1 + tri.p2) / 3;
            const bool lights = dot(at.point - centre, tri.normal()) > 0 && dot(centre - at.point, at.normal) > 0;
            if (lights) {
                EXPECT_GT(p, 0) << at.point << " triangle " << i;
            }
        }
        // Below 1 where a node's bounds admit light that neither child's do (a pair of triangles
        // that both face away from the point): a sample that ends there finds no light, and no
        // light that could light the point loses its chance to it.
        EXPECT_LE(total, 1 + 1e-4) << at.point;
        EXPECT_GT(total, 0) << at.point;
    }
}

// An enclosure of emissive triangles of radiance L facing inwards gives any point inside
// irradiance pi L; a Lambertian sphere of albedo a inside it shows a L, at any bounce count
// (the walls reflect nothing, the sphere never sees itself).
TEST(LightTree, ADiffuseSphereInAGlowingEnclosureShowsAlbedoTimesItsRadiance) {
    Scene s;
    s.camera.origin = {0, 0, -3};
    s.camera.destination = {0, 0, 0};
    s.camera.fovDegrees = 30;
    Material wall = test::pbr({0, 0, 0}, 0, 1, 0);
    wall.emission.color = {1, 1, 1};
    const auto walls = test::addMaterial(s, wall);
    s.looseObjects.add<Sphere>({{0, 0, 0}, 1}, test::addMaterial(s, test::pbr({0.5f, 0.5f, 0.5f}, 0, 1, 0)));
    constexpr int kAround = 16, kUp = 8;
    const auto at = [](int i, int j) {
        const Real phi = 2 * kPi * i / kAround, theta = kPi * j / kUp;
        return Vec3{std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)} * 5;
    };
    for (int i = 0; i < kAround; ++i)
        for (int j = 0; j < kUp; ++j)  // wound so that the front faces the centre
            test::addQuad(s, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j), walls);
    s.flatten();
    RenderSettings settings = test::pathPicture(16, 16);
    settings.threads = 1;
    const Framebuffer one = test::renderPath(s, settings);
    double sum = 0;
    int n = 0;
    for (int y = 4; y < 12; ++y)  // all on the sphere
        for (int x = 4; x < 12; ++x) sum += one.at(x, y).g, ++n;
    EXPECT_NEAR(sum / n, 0.5, 0.01);
    settings.threads = 2;
    EXPECT_EQ(one.pixels(), test::renderPath(s, settings).pixels()) << "the same bits for any thread count";
}

namespace {

// A 4 x 4 panel at z = 0 facing +z, of 8 x 8 cells, emitting 1 under an emission texture (texture
// coordinates (x + 2, y + 2) / 4) that `window` makes black but for its middle 4 x 4 cells, and a
// point light in front of it; without `blackCells`, the panel's lit cells only.
Scene panelWithWindow(bool blackCells) {
    Scene s;
    Material panel = test::pbr({0, 0, 0}, 0, 1, 0);
    panel.emission.color = {1, 1, 1};
    s.textures.push_back({.name = "window", .file = "window.png"});
    panel.emission.texture = 0;
    const auto emissive = test::addMaterial(s, panel);
    constexpr int kCells = 8;
    const auto corner = [](int i, int j) { return Vec3{Real(4 * i) / kCells - 2, Real(4 * j) / kCells - 2, 0}; };
    const auto lit = [](int i) { return i >= 2 && i < 6; };
    for (int i = 0; i < kCells; ++i)
        for (int j = 0; j < kCells; ++j)
            if (blackCells || (lit(i) && lit(j)))
                test::addQuad(s, corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1), emissive);
    s.lights.push_back(Light{{1, 0.5, 0.5}, {0.2f, 0.2f, 0.2f}, 0});
    s.lights.back().falloff = Light::Falloff::InverseSquare;
    s.flatten();
    const auto triangles = s.primitives.all<Triangle>();
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        CornerUvs uvs;
        const Vec3 p[3] = {triangles[i].p0, triangles[i].p1, triangles[i].p2};
        for (int c = 0; c < 3; ++c)
            uvs.values[2 * c] = float(p[c].x + 2) / 4, uvs.values[2 * c + 1] = float(p[c].y + 2) / 4;
        s.primitives.triangleShading().uvs.set(i, uvs);
    }
    return s;
}

Color window(float u, float v) {
    return std::max(std::abs(u - 0.5f), std::abs(v - 0.5f)) < 0.25f ? Color{1, 1, 1} : Color{};
}

}  // namespace

// An emissive panel whose emission texture is black but for a window in its middle (as
// LightsPunctualLamp's shade and stand: an emission factor of 1 on all 6,000 triangles, light only
// where the texture is), beside a point light. Next-event estimation takes the lights by what they
// send, the texture included: it samples as if the black cells were not there (the same choices,
// through the tree and by power), and their density for MIS is 0. Taken by the factor alone, the
// black cells took most samples (the lamp's fireflies: its point lights were chosen for 0.4 % of
// the shadow rays by the tree, 1.5 % by power, near its surfaces).
TEST(LightDistribution, EmissiveTrianglesWeighTheirEmissionTexture) {
    const Scene whole = panelWithWindow(true), lit = panelWithWindow(false);
    const test::FunctionTextures texture(whole, window);
    const Vec3 from{0.3, -0.2, 1}, normal{0, 0, -1};
    for (const LightSampler sampler : {LightSampler::Tree, LightSampler::Power}) {
        const LightDistribution wholePanel({whole, &texture}, sampler), litCells({lit, &texture}, sampler);
        for (int i = 0; i < 1024; ++i) {
            SobolSampler numbers(1, 2, std::uint32_t(i), 0);
            const Real pick = numbers.next1D();
            const auto [u1, u2] = numbers.next2D();
            const std::optional<LightSample> a = wholePanel.sample(from, normal, pick, u1, u2);
            const std::optional<LightSample> b = litCells.sample(from, normal, pick, u1, u2);
            ASSERT_TRUE(a && b);
            ASSERT_EQ(a->source, b->source) << "sample " << i << ", sampler " << int(sampler);
            EXPECT_NEAR(a->pdf, b->pdf, 1e-4 * b->pdf);
            EXPECT_EQ(length(a->direction - b->direction), 0);
        }
        const auto triangles = whole.primitives.all<Triangle>();
        for (std::uint32_t prim = 0; prim < triangles.size(); ++prim) {
            const Vec3 centre = (triangles[prim].p0 + triangles[prim].p1 + triangles[prim].p2) / 3;
            if (window(float(centre.x + 2) / 4, float(centre.y + 2) / 4) != Color{}) continue;
            EXPECT_EQ(wholePanel.pdfTriangle(prim, from, normal, normalize(centre - from), length(centre - from)), 0);
        }
    }
}
