// Single-sided materials (render/material_filter.*, glTF's doubleSided false): a quad seen
// from behind is not there for camera, reflection and refracted rays, through every accelerator
// and both integrators; from the front it is drawn; shadow rays see it as the light does, so it
// shadows where the light sees its front; glass with an inside stays two-sided; a mirroring
// instance keeps the model's front in front; scenes without such materials get no filter.
#include "render/material_filter.h"

#include <gtest/gtest.h>

#include "accel/build.h"
#include "render/surface.h"
#include "render_path_util.h"
#include "render_test_scenes.h"

using namespace rt;

namespace {

const Color kSheetGreen{0, 1, 0}, kBackdropRed{1, 0, 0};

// The sheet: a quad of side 2 at z = 0 whose front (counter-clockwise corners) faces +z, green,
// single-sided unless `doubleSided`. Behind it, seen from -z, a larger red backdrop at z = 3
// facing -z. Both only emit, so a pixel is exactly the colour of what its ray meets.
Scene sheetBeforeBackdrop(bool doubleSided, const Vec3& eye) {
    Scene s;
    s.background = {0, 0, 0.5f};
    s.camera.origin = eye;
    s.camera.destination = {0, 0, eye.z > 0 ? Real(-1) : Real(1)};
    s.camera.fovDegrees = 30;
    Material sheet{
        .name = "sheet", .color = {0, 0, 0}, .phong = {.ambient = 0, .diffuse = 0}, .emission = {.color = kSheetGreen}};
    sheet.doubleSided = doubleSided;
    test::addQuad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, test::addMaterial(s, sheet));
    const auto backdrop = test::addMaterial(s, {.name = "backdrop",
                                                .color = {0, 0, 0},
                                                .phong = {.ambient = 0, .diffuse = 0},
                                                .emission = {.color = kBackdropRed}});
    test::addQuad(s, {-9, -9, 3}, {-9, 9, 3}, {9, 9, 3}, {9, -9, 3}, backdrop);
    s.flatten();
    return s;
}

const Vec3 kFront{0, 0, 2};  // the backdrop is behind this eye
const Vec3 kBehind{0, 0, -5};

// `scene` rendered through the naive list, the BSP and the KD tree (camera packets included),
// each with the scene's material filter; fails unless the three pictures agree bit for bit.
Framebuffer renderEveryTree(const Scene& scene, const RenderSettings& settings) {
    const std::unique_ptr<MaterialFilter> filter = materialFilter({scene, nullptr});
    std::vector<Framebuffer> pictures;
    for (const std::unique_ptr<Accelerator>& accel : test::everyAccelerator(scene.primitives, filter.get())) {
        RenderStats stats;
        pictures.push_back(render(scene, *accel, settings, stats));
    }
    for (const Framebuffer& other : pictures)
        for (int y = 0; y < settings.height; ++y)
            for (int x = 0; x < settings.width; ++x) EXPECT_EQ(other.at(x, y), pictures[0].at(x, y)) << x << "," << y;
    return pictures[0];
}

Color centre(const Framebuffer& f, const RenderSettings& s) { return f.at(s.width / 2, s.height / 2); }

// A white floor at y = 0 under a black sheet of side 2 at y = 1 whose front faces the light,
// above at y = 3, or faces away from it, seen from below the sheet: the centre pixel shows the
// floor under the middle of the sheet, lit by `light` alone (no ambient term, black background).
// `glassElsewhere` adds a glass material no primitive uses, which makes the Whitted tracer walk
// its shadow rays through the scene by nearest hits instead of the any-hit query.
Scene sheetBetweenLightAndFloor(bool doubleSided, bool frontToLight, const Light& light, bool glassElsewhere = false) {
    Scene s;
    s.background = {0, 0, 0};
    s.camera.origin = {0, 0.5, 5};
    s.camera.destination = {0, 0, 0};
    s.camera.fovDegrees = 30;
    Material floor = test::pbr({1, 1, 1}, 0, 1);
    floor.phong.ambient = 0;
    floor.phong.diffuse = 1;
    test::addQuad(s, {-5, 0, -5}, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, test::addMaterial(s, floor));
    Material sheet = test::pbr({0, 0, 0}, 0, 1);
    sheet.phong.ambient = 0;
    sheet.doubleSided = doubleSided;
    const auto sheetId = test::addMaterial(s, sheet);
    if (frontToLight)  // counter-clockwise seen from above
        test::addQuad(s, {-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, sheetId);
    else
        test::addQuad(s, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, {-1, 1, -1}, sheetId);
    if (glassElsewhere) test::addMaterial(s, {.name = "unused glass", .transmission = {.weight = 1}});
    s.lights.push_back(light);
    s.flatten();
    return s;
}

const Light kOverhead{.position = {0, 3, 0}};

// The floor under the sheet, in every tree: in the dark where the light sees the sheet's front,
// lit where it sees its back; a two-sided sheet shadows either way.
Color floorUnderTheSheet(bool doubleSided, bool frontToLight, const Light& light, RenderSettings settings,
                         bool glassElsewhere = false) {
    settings.shadows = true;
    return centre(
        renderEveryTree(sheetBetweenLightAndFloor(doubleSided, frontToLight, light, glassElsewhere), settings),
        settings);
}

}  // namespace

TEST(SingleSided, AQuadSeenFromBehindShowsWhatIsBehindItInEveryTree) {
    const RenderSettings settings = test::picture(24, 24);
    EXPECT_EQ(centre(renderEveryTree(sheetBeforeBackdrop(false, kFront), settings), settings), kSheetGreen);
    EXPECT_EQ(centre(renderEveryTree(sheetBeforeBackdrop(false, kBehind), settings), settings), kBackdropRed);
    EXPECT_EQ(centre(renderEveryTree(sheetBeforeBackdrop(true, kBehind), settings), settings), kSheetGreen)
        << "a two-sided quad is seen from behind (Whitted shows emission from both sides)";
}

// The path tracer takes its rays from the same accelerators: from behind, the backdrop's
// emission; a two-sided quad in the way would show its dark back (emitters shine from the front).
TEST(SingleSided, ThePathTracerSeesThroughTheBackToo) {
    const RenderSettings settings = test::pathPicture(16, 4);
    EXPECT_GT(centre(renderEveryTree(sheetBeforeBackdrop(false, kBehind), settings), settings).r, 0.99f);
    EXPECT_LT(centre(renderEveryTree(sheetBeforeBackdrop(true, kBehind), settings), settings).r, 0.5f);
    EXPECT_GT(centre(renderEveryTree(sheetBeforeBackdrop(false, kFront), settings), settings).g, 0.99f);
}

// Shadow rays (Ray::shadow), traced from the shaded point towards the light, are judged from the
// light's end, in every tree and both queries (the Whitted tracer walks through glass with the
// nearest hit): the sheet blocks a ray that meets its back, since the light beyond sees its front,
// and lets through one that meets its front. Other rays keep passing through the back alone.
TEST(SingleSided, ShadowRaysAreBlockedWhereTheLightSeesTheFront) {
    const Scene scene = sheetBeforeBackdrop(false, kFront);
    const std::unique_ptr<MaterialFilter> filter = materialFilter({scene, nullptr});
    ASSERT_TRUE(filter);
    const auto ray = [](Real z, bool shadow) {
        return Ray{.origin = {0.2, 0.1, z}, .direction = {0, 0, z < 0 ? Real(1) : Real(-1)}, .shadow = shadow};
    };
    for (const std::unique_ptr<Accelerator>& accel : test::everyAccelerator(scene.primitives, filter.get())) {
        RayCounters counters;
        EXPECT_TRUE(accel->occluded(ray(-1, true), 2, counters)) << "towards a light before the front";
        EXPECT_FALSE(accel->occluded(ray(1, true), 2, counters)) << "towards a light behind the back";
        EXPECT_FALSE(accel->occluded(ray(-1, false), 2, counters)) << "from behind";
        EXPECT_TRUE(accel->occluded(ray(1, false), 2, counters)) << "from the front";
        Hit hit;
        ASSERT_TRUE(accel->intersect(ray(-1, true), kInfinity, hit, counters));
        EXPECT_NEAR(hit.t, 1, 1e-6) << "the sheet, whose front the light sees";
        ASSERT_TRUE(accel->intersect(ray(-1, false), kInfinity, hit, counters));
        EXPECT_NEAR(hit.t, 4, 1e-6) << "the backdrop, through the sheet";
        EXPECT_FALSE(accel->intersect(ray(1, true), 2, hit, counters)) << "the light sees the sheet's back";
    }
}

TEST(SingleSided, ASheetShadowsWhereTheLightSeesItsFront) {
    const RenderSettings hard = test::picture(24, 24);
    RenderSettings soft = hard;
    soft.softShadows = true;
    soft.distributedSamples = 8;
    const Light disc{.position = kOverhead.position, .size = 0.3};
    const Light sun{.position = kOverhead.position, .type = Light::Type::Directional, .direction = {0, -1, 0}};
    const Light spot{.position = kOverhead.position, .type = Light::Type::Spot, .direction = {0, -1, 0}};
    const std::pair<Light, RenderSettings> cases[] = {{kOverhead, hard}, {disc, soft}, {sun, hard}, {spot, hard}};
    for (const auto& [light, settings] : cases) {
        for (const bool glass : {false, true}) {
            const std::string which = "light type " + std::to_string(int(light.type)) + ", size " +
                                      std::to_string(light.size) + (glass ? ", glass elsewhere" : "");
            EXPECT_EQ(floorUnderTheSheet(false, true, light, settings, glass), Color{}) << which;
            EXPECT_GT(floorUnderTheSheet(false, false, light, settings, glass).g, 0.5f) << which;
            EXPECT_EQ(floorUnderTheSheet(true, false, light, settings, glass), Color{}) << which << ", two-sided";
        }
    }
}

// The path tracer's shadow rays to the scene's lights follow the same rule.
TEST(SingleSided, ThePathTracersShadowRaysSeeTheSheetAsTheLightDoes) {
    const RenderSettings settings = test::pathPicture(16, 4);
    EXPECT_EQ(floorUnderTheSheet(false, true, kOverhead, settings), Color{});
    EXPECT_GT(floorUnderTheSheet(false, false, kOverhead, settings).g, 0.1f);
    EXPECT_EQ(floorUnderTheSheet(true, false, kOverhead, settings), Color{});
}

// Glass with an inside is entered through its front and left through its back: it stays
// two-sided (KHR_materials_volume: doubleSided has no effect on volume boundaries); a thin
// sheet of glass has no inside, and is single-sided like any surface.
TEST(SingleSided, GlassWithAnInsideKeepsItsBack) {
    for (const bool thin : {false, true}) {
        Scene scene = sheetBeforeBackdrop(false, kFront);
        scene.materials[0].transmission = {.weight = 1, .thin = thin};
        const std::unique_ptr<MaterialFilter> filter = materialFilter({scene, nullptr});
        NaiveAccelerator accel(scene.primitives);
        accel.setHitFilter(filter.get());
        Hit hit;
        RayCounters counters;
        ASSERT_TRUE(accel.intersect({{0.2, 0.1, -1}, {0, 0, 1}}, kInfinity, hit, counters));
        EXPECT_NEAR(hit.t, thin ? 4 : 1, 1e-6) << (thin ? "thin" : "volume");
    }
}

TEST(SingleSided, ScenesWithoutSingleSidedMaterialsHaveNoFilter) {
    EXPECT_FALSE(materialFilter({test::spheresOnFloor(), nullptr}));
    EXPECT_FALSE(materialFilter({sheetBeforeBackdrop(true, kFront), nullptr}));
    EXPECT_TRUE(materialFilter({sheetBeforeBackdrop(false, kFront), nullptr}));
}

// A model instanced under a mirroring transform (x -> -x) in a single-sided material keeps the
// model's front in front (the corners are swapped, with their texture coordinates): glTF orients
// a mesh under a negative determinant so. Two-sided instances keep their corners as they are.
TEST(SingleSided, AMirroredInstanceKeepsTheModelsFront) {
    for (const bool doubleSided : {false, true}) {
        Scene s;
        Model quad;  // x from 0 to 1 at z = 0, front +z; u = x, v = y
        quad.triangleVertices = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
        quad.vertexUvs = {0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1};
        s.models.push_back(quad);
        Material m{.name = "sheet"};
        m.doubleSided = doubleSided;
        s.instances.push_back({0, test::addMaterial(s, m), Transform::scale({-1, 1, 1})});
        s.flatten();
        const Ray down{{-0.25, 0.5, 1}, {0, 0, -1}};  // over the model's x = 0.25
        Hit hit;
        ASSERT_TRUE(s.primitives.view().intersect(0, down, kInfinity, hit) ||
                    s.primitives.view().intersect(1, down, kInfinity, hit));
        const SurfacePoint p = surfaceAt(s.primitives, down, hit);
        EXPECT_EQ(p.frontFace, !doubleSided) << "double-sided " << doubleSided;
        EXPECT_NEAR(p.u, 0.25, 1e-6);
        EXPECT_NEAR(p.v, 0.5, 1e-6);
    }
}
