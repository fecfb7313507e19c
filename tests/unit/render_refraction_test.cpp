#include "render/refraction.h"

#include <cmath>

#include "accel/naive.h"
#include "render/integrators/tracer.h"
#include "render/texture.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

constexpr Real kTolerance = sizeof(Real) == sizeof(float) ? Real(1e-5) : Real(1e-12);

// A material that shows only what its rays bring back: no local shading of its own.
Material glassOfIor(float ior, Color color = {1, 1, 1}) {
    return {.name = "glass",
            .phong = {.ambient = 0, .diffuse = 0},
            .transmission = {.weight = 1, .color = color, .ior = ior}};
}

Material lamp(Color emission) {
    return {.name = "lamp", .phong = {.ambient = 0, .diffuse = 0}, .emission = {.color = emission}};
}

// A quad wound so that its normal (the triangles' winding) is `outward`.
void addFacing(Scene& s, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& outward,
               std::uint32_t material) {
    if (dot(cross(b - a, c - a), outward) > 0)
        test::addQuad(s, a, b, c, d, material);
    else
        test::addQuad(s, a, d, c, b, material);
}

Color traced(const Scene& s, const Ray& ray) {
    const NaiveAccelerator accel(s.primitives);
    RenderSettings settings = test::picture(8, 8);
    settings.shadows = true;
    const Tracer tracer(s, accel, settings);
    SampleRng rng{0, 0, 0};
    RenderCounters counters;
    return tracer.trace(ray, 0, false, rng, counters);
}

// d turned by `angle` towards the unit vector u, which is perpendicular to it.
Vec3 turned(const Vec3& d, const Vec3& u, Real angle) { return d * std::cos(angle) + u * std::sin(angle); }

}  // namespace

TEST(Refraction, DirectionsFollowSnellsLawUpToTheCriticalAngle) {
    const Vec3 n{0, 1, 0};
    for (const Real eta : {Real(1) / Real(1.5), Real(1.5), Real(1)}) {
        for (const Real degrees : {0.0, 20.0, 40.0, 41.5, 42.0, 60.0, 89.0}) {
            const Real theta = degrees * kPi / 180;
            const Vec3 d{std::sin(theta), -std::cos(theta), 0};
            const std::optional<Vec3> t = refractDirection(d, n, eta);
            const Real sinOut = eta * std::sin(theta);
            if (sinOut >= 1) {  // beyond the critical angle, asin(1 / 1.5) = 41.81 degrees
                EXPECT_FALSE(t) << eta << " " << degrees;
                continue;
            }
            ASSERT_TRUE(t) << eta << " " << degrees;
            EXPECT_NEAR(t->x, sinOut, kTolerance);  // n1 sin(theta1) = n2 sin(theta2)
            EXPECT_NEAR(t->y, -std::sqrt(1 - sinOut * sinOut), kTolerance);
            EXPECT_EQ(t->z, 0);
        }
    }
}

TEST(Refraction, SchlicksFresnelRunsFromF0ToOne) {
    EXPECT_FLOAT_EQ(normalReflectance(1.5f), 0.04f);
    EXPECT_FLOAT_EQ(normalReflectance(1.0f), 0.0f);
    EXPECT_FLOAT_EQ(schlickFresnel(1, 0.04f), 0.04f);
    EXPECT_FLOAT_EQ(schlickFresnel(0, 0.04f), 1.0f);  // grazing: a mirror
    EXPECT_LT(schlickFresnel(0.5f, 0.04f), schlickFresnel(0.2f, 0.04f));
    // Leaving glass beyond the critical angle: everything is reflected.
    const Vec3 d = normalize(Vec3{1, -1, 0});  // 45 degrees
    EXPECT_EQ(splitAt({.weight = 1, .ior = 1.5f}, d, {0, 1, 0}, {0, 1, 0}, false).reflected, 1.0f);
    EXPECT_LT(splitAt({.weight = 1, .ior = 1.5f}, d, {0, 1, 0}, {0, 1, 0}, true).reflected, 0.1f);
}

// Head-on, a glass surface reflects ((n - 1) / (n + 1))^2 of what is behind the viewer, from
// either side; what passes sees the black background.
TEST(Refraction, FresnelAtNormalIncidenceIsF0) {
    for (const float ior : {1.5f, 2.42f, 1.33f}) {
        for (const Vec3 outward : {Vec3{0, 0, -1}, Vec3{0, 0, 1}}) {  // the ray enters, or leaves
            Scene s;
            s.camera.origin = {0, 0, -2};
            const auto g = test::addMaterial(s, glassOfIor(ior));
            const auto l = test::addMaterial(s, lamp({1, 1, 1}));
            addFacing(s, {-9, -9, 0}, {9, -9, 0}, {9, 9, 0}, {-9, 9, 0}, outward, g);
            test::addQuad(s, {-9, -9, -5}, {-9, 9, -5}, {9, 9, -5}, {9, -9, -5}, l);  // behind the viewer
            s.flatten();
            const float f0 = (ior - 1) / (ior + 1) * ((ior - 1) / (ior + 1));
            const Color c = traced(s, {{0, 0, -2}, {0, 0, 1}});
            EXPECT_NEAR(c.r, f0, 1e-6) << ior;
            EXPECT_EQ(c.r, c.g);
            EXPECT_EQ(c.r, c.b);
        }
    }
}

// A glass sphere (ior 1.5) in front of an emitting checkerboard: each pixel through the
// sphere shows the square that Snell's law, applied by hand at both surfaces (angles, not
// vectors), puts there, and many of them differ from the square straight behind.
TEST(Refraction, AGlassSphereDisplacesACheckerboardWhereSnellsLawPutsIt) {
    const Real ior = 1.5, radius = 1, wallZ = 3.25, square = 0.5;
    Scene s;
    s.camera.origin = {0, 0, -6};
    s.camera.fovDegrees = 30;
    s.textures.push_back(
        {.name = "c", .kind = Texture::Kind::Checker, .colorA = {1, 0, 0}, .colorB = {0, 0, 1}, .size = 0.5});
    Material wall = lamp({1, 1, 1});
    wall.emission.texture = 0;
    s.looseObjects.add<Sphere>({{0, 0, 0}, radius}, test::addMaterial(s, glassOfIor(float(ior))));
    test::addQuad(s, {-20, -20, wallZ}, {20, -20, wallZ}, {20, 20, wallZ}, {-20, 20, wallZ},
                  test::addMaterial(s, wall));
    s.flatten();
    const NaiveAccelerator accel(s.primitives);
    const int size = 48;
    const Tracer tracer(s, accel, test::picture(size, size));
    const CameraRays camera(s.camera, size, size);
    // The checker colour of the wall at q, and whether q is safely inside its square.
    const auto squareAt = [&](const Vec3& q, bool& clear) {
        const Real margin = 0.03;
        clear = std::abs(q.x / square - std::round(q.x / square)) * square > margin &&
                std::abs(q.y / square - std::round(q.y / square)) * square > margin;
        SurfacePoint p;
        p.point = q;
        p.geometricNormal = {0, 0, -1};
        return textureColor({s}, 0, p);
    };
    const auto onWall = [&](const Vec3& p, const Vec3& d) { return p + d * ((wallZ - p.z) / d.z); };
    int checked = 0, displaced = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const Ray ray = camera.at(x + 0.5, y + 0.5);
            const Vec3 toCentre = -ray.origin;
            const Real along = dot(toCentre, ray.direction);
            const Vec3 across = toCentre - ray.direction * along;  // from the ray to the centre
            const Real h = length(across);
            if (h > 0.9 * radius || h < 1e-3) continue;  // keep off the rim and the axis
            const Real in = std::asin(h / radius), out = std::asin(h / radius / ior);
            const Vec3 u = across / h;
            const Vec3 entry = ray.at(along - std::sqrt(radius * radius - h * h));
            const Vec3 inside = turned(ray.direction, u, in - out);
            const Vec3 exit = entry + inside * (2 * radius * std::cos(out));
            const Vec3 leaving = turned(ray.direction, u, 2 * (in - out));
            bool clear = false, straightClear = false;
            const Color expected = squareAt(onWall(exit, leaving), clear);
            const Color straight = squareAt(onWall(ray.origin, ray.direction), straightClear);
            if (!clear) continue;
            RenderCounters counters;
            const Color seen = tracer.pixel(x, y, counters);
            ++checked;
            EXPECT_EQ(seen.r > seen.b, expected.r > expected.b) << "pixel " << x << ", " << y;
            EXPECT_GT(std::max(seen.r, seen.b), 0.8f);  // (1 - F)^2 of it at least
            displaced += straightClear && straight != expected;
        }
    }
    EXPECT_GT(checked, 200);
    EXPECT_GT(displaced, checked / 5);
}

// A right-angle prism: a ray entering its short face head-on meets the long face at 45
// degrees. Glass of index 1.5 (critical angle 41.8 degrees) reflects it totally, out through
// the other short face to a red lamp: (1 - F0)^2 of the lamp arrives. At index 1.3 (critical
// angle 50.3 degrees) most of it passes the long face and misses the lamp.
TEST(Refraction, APrismReflectsTotallyBeyondTheCriticalAngle) {
    for (const float ior : {1.5f, 1.3f}) {
        Scene s;
        const auto g = test::addMaterial(s, glassOfIor(ior));
        const auto red = test::addMaterial(s, lamp({1, 0, 0}));
        const Real y0 = -5, y1 = 5;
        addFacing(s, {-1, y0, 0}, {1, y0, 0}, {1, y1, 0}, {-1, y1, 0}, {0, 0, -1}, g);  // faces the viewer
        addFacing(s, {1, y0, 0}, {1, y0, 2}, {1, y1, 2}, {1, y1, 0}, {1, 0, 0}, g);     // faces the lamp
        addFacing(s, {-1, y0, 0}, {1, y0, 2}, {1, y1, 2}, {-1, y1, 0}, {-1, 0, 1}, g);  // the long face
        test::addQuad(s, {4, -9, -9}, {4, 9, -9}, {4, 9, 6}, {4, -9, 6}, red);  // what passes reaches x = 4 at z = 11
        s.flatten();
        const Color c = traced(s, {{0, 0, -3}, {0, 0, 1}});
        if (ior == 1.5f) {
            const float f0 = normalReflectance(ior);
            EXPECT_NEAR(c.r, (1 - f0) * (1 - f0), 0.005f);
        } else {
            EXPECT_LT(c.r, 0.2f);
        }
        EXPECT_EQ(c.g, 0.0f);
    }
}

// A floor lit from straight above through a pane of coloured glass: the light arrives tinted
// by the glass's colour and reduced by Fresnel's reflection at normal incidence.
TEST(Refraction, ShadowsThroughGlassAreTinted) {
    const auto floorSeen = [](std::optional<Material> pane) {
        Scene s;
        const auto floor = test::addMaterial(s, {.name = "floor", .phong = {.ambient = 0, .diffuse = 1}});
        test::addQuad(s, {-9, 0, -9}, {-9, 0, 9}, {9, 0, 9}, {9, 0, -9}, floor);
        if (pane) test::addQuad(s, {-1, 5, -1}, {-1, 5, 1}, {1, 5, 1}, {1, 5, -1}, test::addMaterial(s, *pane));
        s.lights.push_back({{0, 10, 0}, {1, 1, 1}});
        s.flatten();
        return traced(s, {{3, 1, 0}, normalize(Vec3{-3, -1, 0})});
    };
    EXPECT_EQ(floorSeen(std::nullopt), (Color{1, 1, 1}));
    const Color tint{1, 0.5f, 0.25f};
    const Color through = floorSeen(glassOfIor(1.5f, tint));
    EXPECT_NEAR(through.r, 0.96f, 1e-5);
    EXPECT_NEAR(through.g, 0.48f, 1e-5);
    EXPECT_NEAR(through.b, 0.24f, 1e-5);
    Material opaque = glassOfIor(1.5f, tint);
    opaque.transmission.weight = 0;
    EXPECT_EQ(floorSeen(opaque), (Color{}));
}

// Beer-Lambert: a ray that crosses d = 2 of a glass block with attenuation colour 0.5 at
// distance 1 keeps 0.5^2 of what is behind it (besides the Fresnel losses at both faces).
TEST(Refraction, AVolumeAbsorbsAlongTheDistanceInside) {
    const Color behind = [] {
        Scene s;
        Material m = glassOfIor(1.0f);  // no bending, no reflection: only the absorption
        m.transmission.attenuationColor = {0.5f, 0.25f, 1};
        m.transmission.attenuationDistance = 1;
        const auto g = test::addMaterial(s, m);
        addFacing(s, {-9, -9, 0}, {9, -9, 0}, {9, 9, 0}, {-9, 9, 0}, {0, 0, -1}, g);
        addFacing(s, {-9, -9, 2}, {9, -9, 2}, {9, 9, 2}, {-9, 9, 2}, {0, 0, 1}, g);
        test::addQuad(s, {-9, -9, 5}, {-9, 9, 5}, {9, 9, 5}, {9, -9, 5}, test::addMaterial(s, lamp({1, 1, 1})));
        s.flatten();
        return traced(s, {{0, 0, -3}, {0, 0, 1}});
    }();
    EXPECT_NEAR(behind.r, 0.25f, 1e-3);  // the ray starts an epsilon inside
    EXPECT_NEAR(behind.g, 0.0625f, 1e-3);
    EXPECT_EQ(behind.b, 1.0f);
}

namespace {

// A glass ball of sigma `spread` before a red and blue checker wall, seen under distributed ray
// tracing (-D d, 16 rays a lobe): how much red and blue vary over the pixels inside the ball.
double contrastThroughGlass(float spread) {
    Scene s;
    s.camera.origin = {0, 0, -6};
    s.camera.destination = {0, 0, 0};
    s.camera.fovDegrees = 20;
    s.textures.push_back(
        {.name = "c", .kind = Texture::Kind::Checker, .colorA = {1, 0, 0}, .colorB = {0, 0, 1}, .size = 0.25});
    Material wall = lamp({1, 1, 1});
    wall.emission.texture = 0;
    Material ball = glassOfIor(1.5f);
    ball.phong.spread = spread;
    s.looseObjects.add<Sphere>({{0, 0, 0}, 1}, test::addMaterial(s, ball));
    test::addQuad(s, {-20, -20, 3}, {20, -20, 3}, {20, 20, 3}, {-20, 20, 3}, test::addMaterial(s, wall));
    s.flatten();
    RenderSettings settings = test::picture(24, 24);
    settings.glossyReflections = true;
    settings.distributedSamples = 16;
    const Framebuffer image = test::renderNaive(s, settings).image;
    double sum = 0, squares = 0;
    int n = 0;
    for (int y = 8; y < 16; ++y)
        for (int x = 8; x < 16; ++x, ++n) {
            const double v = image.at(x, y).r - image.at(x, y).b;
            sum += v;
            squares += v * v;
        }
    return std::sqrt(squares / n - (sum / n) * (sum / n));
}

}  // namespace

// Rough glass spreads its transmitted ray as glossy reflection does (thesis 2.6.2): the checker
// behind a frosted ball blurs to purple.
TEST(Refraction, RoughGlassBlursWhatIsSeenThroughItUnderDistributedRayTracing) {
    const double sharp = contrastThroughGlass(0), frosted = contrastThroughGlass(0.3f);
    EXPECT_GT(sharp, 0.5);
    EXPECT_LT(frosted, sharp / 3) << "standard deviation of red - blue: sharp " << sharp << ", frosted " << frosted;
}
