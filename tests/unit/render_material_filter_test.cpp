// Single-sided materials (render/material_filter.*, glTF's doubleSided false): a quad seen
// from behind is not there for any ray, through every accelerator and both integrators; from
// the front it is drawn; glass with an inside stays two-sided; a mirroring instance keeps the
// model's front in front; scenes without such materials get no filter.
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
    Material sheet{.name = "sheet", .color = {0, 0, 0}, .ambient = 0, .diffuse = 0, .emission = kSheetGreen};
    sheet.doubleSided = doubleSided;
    test::addQuad(s, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, test::addMaterial(s, sheet));
    const auto backdrop = test::addMaterial(
        s, {.name = "backdrop", .color = {0, 0, 0}, .ambient = 0, .diffuse = 0, .emission = kBackdropRed});
    test::addQuad(s, {-9, -9, 3}, {-9, 9, 3}, {9, 9, 3}, {9, -9, 3}, backdrop);
    s.flatten();
    return s;
}

const Vec3 kFront{0, 0, 2};  // the backdrop is behind this eye
const Vec3 kBehind{0, 0, -5};

// `scene` rendered through the naive list, the BSP and the KD tree (camera packets included),
// each with the scene's material filter; fails unless the three pictures agree bit for bit.
Framebuffer renderEveryTree(const Scene& scene, const RenderSettings& settings) {
    const std::unique_ptr<MaterialFilter> filter = materialFilter(scene, nullptr);
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

// Shadow rays, traced from the shaded point towards the light, are blocked by the front alone,
// in every tree: light reaches a point behind the sheet's back, not one before its front.
TEST(SingleSided, ShadowRaysPassThroughTheBackOnly) {
    const Scene scene = sheetBeforeBackdrop(false, kFront);
    const std::unique_ptr<MaterialFilter> filter = materialFilter(scene, nullptr);
    ASSERT_TRUE(filter);
    for (const std::unique_ptr<Accelerator>& accel : test::everyAccelerator(scene.primitives, filter.get())) {
        RayCounters counters;
        EXPECT_FALSE(accel->occluded({{0.2, 0.1, -1}, {0, 0, 1}}, 2, counters)) << "from behind";
        EXPECT_TRUE(accel->occluded({{0.2, 0.1, 1}, {0, 0, -1}}, 2, counters)) << "from the front";
        Hit hit;
        ASSERT_TRUE(accel->intersect({{0.2, 0.1, -1}, {0, 0, 1}}, kInfinity, hit, counters));
        EXPECT_NEAR(hit.t, 4, 1e-6) << "the backdrop, through the sheet";
    }
}

// Glass with an inside is entered through its front and left through its back: it stays
// two-sided (KHR_materials_volume: doubleSided has no effect on volume boundaries); a thin
// sheet of glass has no inside, and is single-sided like any surface.
TEST(SingleSided, GlassWithAnInsideKeepsItsBack) {
    for (const bool thin : {false, true}) {
        Scene scene = sheetBeforeBackdrop(false, kFront);
        scene.materials[0].transmission = {.weight = 1, .thin = thin};
        const std::unique_ptr<MaterialFilter> filter = materialFilter(scene, nullptr);
        NaiveAccelerator accel(scene.primitives);
        accel.setHitFilter(filter.get());
        Hit hit;
        RayCounters counters;
        ASSERT_TRUE(accel.intersect({{0.2, 0.1, -1}, {0, 0, 1}}, kInfinity, hit, counters));
        EXPECT_NEAR(hit.t, thin ? 4 : 1, 1e-6) << (thin ? "thin" : "volume");
    }
}

TEST(SingleSided, ScenesWithoutSingleSidedMaterialsHaveNoFilter) {
    EXPECT_FALSE(materialFilter(test::spheresOnFloor(), nullptr));
    EXPECT_FALSE(materialFilter(sheetBeforeBackdrop(true, kFront), nullptr));
    EXPECT_TRUE(materialFilter(sheetBeforeBackdrop(false, kFront), nullptr));
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
