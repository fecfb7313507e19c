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
    lamp.emission = kLampRadiance;
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
    const LightDistribution tree(s, nullptr, LightSampler::Tree), power(s, nullptr, LightSampler::Power);
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
    const LightDistribution lights(s, nullptr, LightSampler::Tree);
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
    wall.emission = {1, 1, 1};
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
