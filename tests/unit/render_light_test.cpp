// Light types (render/lights/light_sample.*, scene/light.h): each matches its formula at measured
// points of a white diffuse floor, with the cosine, the inverse-square falloff, the range
// window and the spot cone written out here independently of the renderer's code.
#include <gtest/gtest.h>

#include <cmath>

#include "accel/naive.h"
#include "render/integrators/tracer.h"
#include "render/lights/light_sample.h"
#include "render_test_scenes.h"
#include "scene/spot_cone.h"

using namespace rt;

namespace {

// A white floor at y = 0 with diffuse 1 and nothing else (no ambient): a point shows the
// irradiance the light gives it, cosine included.
Scene floorLitBy(const Light& light) {
    Scene s;
    test::addMaterial(s, {.name = "white", .color = {1, 1, 1}, .phong = {.ambient = 0, .diffuse = 1}});
    test::addQuad(s, {-100, 0, -100}, {-100, 0, 100}, {100, 0, 100}, {100, 0, -100}, 0);
    s.lights.push_back(light);
    s.flatten();
    return s;
}

// What a ray straight down onto the floor at (x, 0, z) shows; `c` counts the rays.
float floorAt(const Scene& s, Real x, Real z, bool shadows, RenderCounters& c) {
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = test::picture(8, 8);
    settings.shadows = shadows;
    const Tracer tracer(s, accel, settings);
    SampleRng rng{0, 0, 0};
    return tracer.trace({{x, 1, z}, {0, -1, 0}}, 0, false, rng, c).g;
}

float floorAt(const Scene& s, Real x, Real z, bool shadows = false) {
    RenderCounters c;
    return floorAt(s, x, z, shadows, c);
}

constexpr double kDegree = 3.14159265358979323846 / 180;

}  // namespace

// Thesis point lights: the colour times the cosine, at any distance.
TEST(Lights, PointWithoutFalloffGivesItsColourTimesTheCosine) {
    Light light{{0, 4, 0}, {0.5f, 0.5f, 0.5f}, 0};
    const Scene s = floorLitBy(light);
    for (double x : {0.0, 3.0, 40.0}) EXPECT_NEAR(floorAt(s, x, 0), 0.5 * 4 / std::hypot(4.0, x), 1e-5) << x;
}

TEST(Lights, PointWithInverseSquareFalloff) {
    Light light{{0, 2, 0}, {3, 3, 3}, 0};
    light.falloff = Light::Falloff::InverseSquare;
    const Scene s = floorLitBy(light);
    for (double x : {0.0, 1.0, 2.0, 5.0}) {
        const double d2 = 4 + x * x;
        EXPECT_NEAR(floorAt(s, x, 0), 3 / d2 * (2 / std::sqrt(d2)), 1e-5) << x;
    }
}

// KHR_lights_punctual's recommended window: max(min(1 - (d/range)^4, 1), 0) / d^2.
TEST(Lights, RangeFadesTheLightToNothing) {
    Light light{{0, 2, 0}, {3, 3, 3}, 0};
    light.falloff = Light::Falloff::InverseSquare;
    light.range = 4;
    const Scene s = floorLitBy(light);
    for (double x : {0.0, 2.0, 3.0}) {
        const double d2 = 4 + x * x, d = std::sqrt(d2);
        const double window = 1 - std::pow(d / 4, 4);
        EXPECT_NEAR(floorAt(s, x, 0), 3 * window / d2 * (2 / d), 1e-5) << x;
    }
    EXPECT_EQ(floorAt(s, 3.5, 0), 0.0f);  // d = 4.03: beyond the range
}

// Directional: the colour times the cosine everywhere, no falloff.
TEST(Lights, DirectionalGivesItsIrradianceTimesTheCosine) {
    Light light;
    light.type = Light::Type::Directional;
    light.direction = normalize(Vec3{1, -2, 0});
    light.color = {0.8f, 0.8f, 0.8f};
    const Scene s = floorLitBy(light);
    for (double x : {0.0, 10.0, 90.0}) EXPECT_NEAR(floorAt(s, x, 7), 0.8 * 2 / std::sqrt(5.0), 1e-5) << x;
}

// Spot: full inside the inner cone, nothing outside the outer one, and between them the
// reference code's ((cos a - cos outer) / (cos inner - cos outer))^2.
TEST(Lights, SpotConeFallsOffAsKhrLightsPunctualSays) {
    Light light{{0, 3, 0}, {2, 2, 2}, 0};
    light.type = Light::Type::Spot;
    light.direction = {0, -1, 0};
    light.falloff = Light::Falloff::InverseSquare;
    light.innerConeDegrees = 10;
    light.outerConeDegrees = 30;
    const Scene s = floorLitBy(light);
    for (double angle : {0.0, 5.0, 15.0, 20.0, 28.0, 35.0}) {
        const double x = 3 * std::tan(angle * kDegree), d2 = 9 + x * x, c = std::cos(angle * kDegree);
        const double t =
            std::clamp((c - std::cos(30 * kDegree)) / (std::cos(10 * kDegree) - std::cos(30 * kDegree)), 0.0, 1.0);
        EXPECT_NEAR(floorAt(s, 0, x), 2 / d2 * c * t * t, 1e-5) << angle;
    }
    EXPECT_EQ(floorAt(s, 0, 3 * std::tan(31 * kDegree)), 0.0f);
}

// The one conversion of a spot's angles (scene/spot_cone.h), which the sampler, the
// light tree and the power estimate share: radians, the inner angle no wider than the outer, and
// the sampler's falloff reaching 1 and 0 at the cone's two cosines.
TEST(Lights, SpotConeOfConvertsTheAnglesOnceForEveryUser) {
    Light light;
    light.type = Light::Type::Spot;
    light.innerConeDegrees = 10;
    light.outerConeDegrees = 30;
    const SpotCone cone = spotConeOf(light);
    EXPECT_NEAR(cone.inner, 10 * kDegree, 1e-6);
    EXPECT_NEAR(cone.outer, 30 * kDegree, 1e-6);
    EXPECT_EQ(cone.cosInner, std::cos(cone.inner));
    EXPECT_EQ(cone.cosOuter, std::cos(cone.outer));
    EXPECT_NEAR(spotCone(light, cone.cosInner), 1, 1e-6);
    EXPECT_EQ(spotCone(light, cone.cosOuter), 0);

    light.innerConeDegrees = 40;  // past the outer angle: a hard edge at the outer one
    EXPECT_EQ(spotConeOf(light).inner, spotConeOf(light).outer);
}

// A directional light is infinitely far: an occluder 1000 units up its beam still shadows
// (the point light 100 scene radii away that rt used to put in its place would be below it).
TEST(Lights, DirectionalShadowsReachInfinitelyFar) {
    Light light;
    light.type = Light::Type::Directional;
    light.direction = {0, -1, 0};
    Scene s = floorLitBy(light);
    s.looseObjects.add<Sphere>({{0, 1000, 0}, 1}, 0);
    s.flatten();
    EXPECT_EQ(floorAt(s, 0, 0, true), 0.0f);
    EXPECT_NEAR(floorAt(s, 3, 0, true), 1.0f, 1e-6);
    EXPECT_NEAR(floorAt(s, 0, 0, false), 1.0f, 1e-6);
}

// A spot's back and the region outside its cone send no shadow rays.
TEST(Lights, NoShadowRayWhereALightSendsNothing) {
    Light light{{0, 3, 0}, {1, 1, 1}, 0};
    light.type = Light::Type::Spot;
    light.direction = {0, -1, 0};
    const Scene s = floorLitBy(light);
    RenderCounters c;
    floorAt(s, 50, 0, true, c);
    EXPECT_EQ(c.shadow.rays, 0u);
    floorAt(s, 0, 0, true, c);
    EXPECT_EQ(c.shadow.rays, 1u);
}

TEST(Lights, IncidenceOfAThesisPointLightIsTheNormalizedDirection) {
    const Light light{{1, 2, 3}, {0.25f, 0.5f, 1}, 0};
    const Vec3 p{-0.3, 0.7, 0.1};
    const LightIncidence in = lightIncidence(light, p);
    EXPECT_EQ(in.toLight, normalize(light.position - p));  // bit for bit: thesis pictures stay the same
    EXPECT_EQ(in.color, light.color);
    EXPECT_EQ(in.distance, length(light.position - p));
}

// The ambient term sums the colours of the lights without falloff (thesis 2.1.3); an
// inverse-square light's colour is an intensity at distance 1, and adds nothing to it.
TEST(Lights, AmbientSumsOnlyLightsWithoutFalloff) {
    Light below{{0, -5, 0}, {0.5f, 0.5f, 0.5f}, 0};  // under the floor: ambient only
    Scene s = floorLitBy(below);
    s.materials[0].phong.ambient = 0.5f;
    EXPECT_NEAR(floorAt(s, 0, 0), 0.25f, 1e-6);
    s.lights[0].falloff = Light::Falloff::InverseSquare;
    EXPECT_EQ(floorAt(s, 0, 0), 0.0f);
}
