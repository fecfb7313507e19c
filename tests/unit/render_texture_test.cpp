#include "render/texture.h"

#include "accel/naive.h"
#include "render/integrators/tracer.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

TEST(Texture, CoordinatesAreScaledRotatedThenOffset) {
    Texture t;
    t.scale = {2, 3};
    t.rotation = float(kPi / 2);
    t.offset = {0.5f, 0.25f};
    const TexCoord uv = UvTransform(t)(1, 0);  // scaled (2, 0), rotated (0, -2), offset
    EXPECT_NEAR(uv.s, 0.5f, 1e-6);
    EXPECT_NEAR(uv.t, -1.75f, 1e-6);
    const TexCoord same = UvTransform(Texture{})(0.25, 0.75);
    EXPECT_EQ(same.s, 0.25f);
    EXPECT_EQ(same.t, 0.75f);
}

// Derivatives (the filter's footprint) are scaled and rotated, not offset.
TEST(Texture, DerivativesTakeTheLinearPartOfTheTransform) {
    Texture t;
    t.scale = {2, 3};
    t.rotation = float(kPi / 2);
    t.offset = {0.5f, 0.25f};
    SurfacePoint p;
    p.dudx = 1;  // one pixel right: u grows by 1
    p.dvdy = 1;  // one pixel down: v grows by 1
    const TexCoord at = UvTransform(t)(p);
    EXPECT_NEAR(at.dsdx, 0, 1e-6);
    EXPECT_NEAR(at.dtdx, -2, 1e-6);
    EXPECT_NEAR(at.dsdy, 3, 1e-6);
    EXPECT_NEAR(at.dtdy, 0, 1e-6);
}

TEST(Texture, CheckerAlternatesCubesAndIsOneColourOnABoundaryPlane) {
    Scene scene;
    scene.textures.push_back({.name = "c", .kind = Texture::Kind::Checker, .colorA = {1, 0, 0}, .colorB = {0, 0, 1}});
    SurfacePoint s;
    s.geometricNormal = {0, 1, 0};  // a floor at y = 0 seen from above: the cubes below it
    s.point = {0.5, 0, 0.5};
    const Color a = textureColor({scene}, 0, s);
    s.point = {1.5, 0, 0.5};
    const Color b = textureColor({scene}, 0, s);
    s.point = {1.5, 0, 1.5};
    EXPECT_EQ(textureColor({scene}, 0, s), a);
    EXPECT_NE(a, b);
    EXPECT_TRUE((a == Color{1, 0, 0} && b == Color{0, 0, 1}) || (a == Color{0, 0, 1} && b == Color{1, 0, 0}));
    // Image textures without lookups are white: the material's colour alone.
    scene.textures.push_back({.name = "i", .path = "x.png"});
    EXPECT_EQ(textureColor({scene}, 1, s), (Color{1, 1, 1}));
}

TEST(Tracer, AnEmitterIsSeenInAMirrorWithoutLights) {
    // A mirror at z = 0 facing -z, an emitting quad behind the ray's start at z = -5; no light.
    Scene s;
    s.camera.origin = {0, 0, -2};
    s.camera.destination = {0, 0, 0};
    const auto mirror =
        test::addMaterial(s, {.name = "mirror", .phong = {.ambient = 0, .diffuse = 0, .reflection = 1}});
    const auto lamp = test::addMaterial(s, {.name = "lamp",
                                            .color = {0, 0, 0},
                                            .phong = {.ambient = 0, .diffuse = 0},
                                            .emission = {.color = {1, 0.5f, 0.25f}}});
    test::addQuad(s, {-9, -9, 0}, {9, -9, 0}, {9, 9, 0}, {-9, 9, 0}, mirror);
    test::addQuad(s, {-9, -9, -5}, {-9, 9, -5}, {9, 9, -5}, {9, -9, -5}, lamp);
    s.flatten();
    const NaiveAccelerator accel(s.primitives);
    const Tracer tracer(s, accel, test::picture(4, 4));
    SampleRng rng{0, 0, 0};
    RenderCounters c;
    EXPECT_EQ(tracer.trace({{0, 0, -2}, {0, 0, 1}}, 0, false, rng, c), (Color{1, 0.5f, 0.25f}));
    EXPECT_EQ(tracer.trace({{0, 0, -2}, {0, 0, -1}}, 0, false, rng, c), (Color{1, 0.5f, 0.25f}));  // directly
}

namespace {

// Every texel mid grey; counts the lookups of colour (lookup) and of data (data).
class CountingTextures : public ImageTextures {
public:
    using ImageTextures::ImageTextures;
    Color lookup(std::uint32_t, const TexCoord&) const override {
        ++colors;
        return {0.5f, 0.5f, 0.5f};
    }
    Color data(std::uint32_t, const TexCoord&) const override {
        ++datas;
        return {0.5f, 0.5f, 0.5f};
    }
    float alpha(std::uint32_t, float, float, bool) const override { return 1; }
    bool hasAlpha(std::uint32_t, bool) const override { return false; }
    mutable int colors = 0, datas = 0;
};

// The counted lookups of a 4 x 4 render of `scene`, one thread.
CountingTextures countLookups(const Scene& scene) {
    const NaiveAccelerator accel(scene.primitives);
    CountingTextures images(scene);
    const Tracer tracer({scene, &images}, accel, test::picture(4, 4));
    RenderCounters c;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) tracer.pixel(x, y, c);
    return images;
}

}  // namespace

// The roughness only widens the footprint of the one mirror ray (no distributed ray tracing):
// a ray that leaves the scene reads none, the lookups of a textured glTF material's reflection.
TEST(Tracer, AMirrorRayThatLeavesTheSceneReadsNoRoughnessTexture) {
    Scene s;
    s.camera.origin = {0, 0, -2};
    s.camera.destination = {0, 0, 0};
    s.camera.fovDegrees = 60;
    s.textures.push_back({.name = "colour", .path = "colour.png"});
    s.textures.push_back({.name = "roughness", .path = "roughness.png"});
    Material m{.name = "metal", .phong = {.reflection = 0.5f}, .colorTexture = 0};
    m.pbr.factors = MetallicRoughness{.metallic = 1, .roughness = 1};
    m.pbr.texture = 1;
    const auto metal = test::addMaterial(s, m);
    test::addQuad(s, {-9, -9, 0}, {9, -9, 0}, {9, 9, 0}, {-9, 9, 0}, metal);
    Scene facing = s;  // the same with a wall behind the camera, where the mirror rays land
    test::addQuad(facing, {-9, -9, -5}, {-9, 9, -5}, {9, 9, -5}, {9, -9, -5}, metal);
    s.flatten();
    facing.flatten();
    const CountingTextures alone = countLookups(s);
    EXPECT_EQ(alone.colors, 16);
    EXPECT_EQ(alone.datas, 0);
    const CountingTextures walled = countLookups(facing);
    EXPECT_GT(walled.datas, 0);
}
