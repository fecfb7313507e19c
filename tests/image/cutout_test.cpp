// Cut-outs (render/cutout.*, geometry/hit_filter.h): a quad whose material is cut out by a
// generated RGBA picture is seen through where the mask is clear and casts a shadow of the
// mask's shape, through every accelerator alike; the alpha lookups of TextureFiles.
#include "render/material_filter.h"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../unit/render_test_scenes.h"
#include "accel/build.h"
#include "accel/naive.h"
#include "image/texture_files.h"
#include "render/camera_rays.h"
#include "render/renderer.h"

using namespace rt;

namespace {

constexpr int kSize = 16;  // texels a side
constexpr int kCell = 4;   // the mask is a checker of kCell x kCell texel cells

bool opaqueTexel(int x, int y) { return (x / kCell + y / kCell) % 2 == 0; }

// A white kSize x kSize picture with `channels` channels whose last (alpha, or the grey of a
// one-channel mask) is the checker: 1 where opaqueTexel, else 0.
void writeMask(const std::string& path, int channels) {
    OIIO::ImageSpec spec(kSize, kSize, channels, OIIO::TypeDesc::UINT8);
    if (channels == 4) spec.alpha_channel = 3;
    OIIO::ImageBuf picture(spec);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            float texel[4] = {1, 1, 1, 1};
            texel[channels - 1] = opaqueTexel(x, y) ? 1.0f : 0.0f;
            picture.setpixel(x, y, texel);
        }
    ASSERT_TRUE(picture.write(path));
}

// Whether the mask is opaque at texture coordinates (u, v), and whether (u, v) lies at least
// half a texel from every cell edge (away from the bilinear blend across it).
bool opaqueAt(Real u, Real v) { return opaqueTexel(int(u * kSize), int(v * kSize)); }
bool clearOfEdges(Real u, Real v) {
    const auto clear = [](Real c) {
        const Real inCell = std::fmod(c * kSize, Real(kCell));
        return c > 0 && c < 1 && inCell > 0.5 && inCell < kCell - 0.5;
    };
    return clear(u) && clear(v);
}

// The cut-out quad: x in [x0, x0 + 1], y in [-0.5, 0.5] at height z, texture coordinates
// (u, v) = (x - x0, y + 0.5).
void addCutoutQuad(Scene& s, Real x0, Real z, std::uint32_t material) {
    Model quad;
    const auto X = float(x0), Z = float(z);
    quad.triangleVertices = {X, -0.5f, Z, X + 1, -0.5f, Z, X + 1, 0.5f, Z, X, -0.5f, Z, X + 1, 0.5f, Z, X, 0.5f, Z};
    quad.vertexUvs = {0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1};
    s.models.push_back(quad);
    s.instances.push_back({std::uint32_t(s.models.size() - 1), material, Transform()});
}

Material cutoutMaterial(std::uint32_t texture) {
    Material m{.name = "leaf", .color = {0, 1, 0}, .phong = {.ambient = 1, .diffuse = 0}};
    m.opacity.texture = texture;
    m.opacity.cutoff = 0.5f;
    return m;
}

constexpr Real kQuadX = 0.5, kQuadZ = 2;
const Vec3 kLight{1e4, 0, 1e4 + kQuadZ};  // far, 45 degrees from +x: the quad's shadow falls at x - 2

// A white floor at z = 0 seen from above, the cut-out quad over it, a light from the side.
Scene floorUnderCutout(const std::string& mask) {
    Scene s;
    s.camera.origin = {0, 0, 10};
    s.camera.destination = {0, 0, 0};
    s.camera.fovDegrees = 2 * std::atan(2.0 / 10) * 180 / kPi;  // x from -2 to 2 on the floor
    s.textures.push_back({.name = "mask", .path = mask});
    const auto floor = test::addMaterial(s, {.name = "floor", .phong = {.ambient = 0.1f, .diffuse = 0.9f}});
    test::addQuad(s, {-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}, floor);
    addCutoutQuad(s, kQuadX, kQuadZ, test::addMaterial(s, cutoutMaterial(0)));
    s.lights.push_back({kLight});
    s.flatten();
    return s;
}

}  // namespace

TEST(Cutout, TheShadowOfACutoutQuadHasTheMasksShape) {
    const std::string path = testing::TempDir() + "/cutout-mask.png";
    writeMask(path, 4);
    const Scene scene = floorUnderCutout(path);
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    const std::unique_ptr<MaterialFilter> filter = materialFilter({scene, &images});
    ASSERT_TRUE(filter);
    RenderSettings settings = test::picture(200, 200);
    settings.shadows = true;
    const NaiveAccelerator plain(scene.primitives);  // without the filter: where the floor is
    const CameraRays camera(scene.camera, settings.width, settings.height);
    int compared = 0, agree = 0;
    std::vector<Framebuffer> pictures;
    for (const std::unique_ptr<Accelerator>& accel : test::everyAccelerator(scene.primitives, filter.get())) {
        RenderStats stats;
        pictures.push_back(render({scene, &images}, *accel, settings, stats));
    }
    const Framebuffer& image = pictures[0];
    for (int y = 0; y < settings.height; ++y)
        for (int x = 0; x < settings.width; ++x) {
            const Ray ray = camera.at(x + 0.5, y + 0.5);
            Hit hit;
            RayCounters counters;
            ASSERT_TRUE(plain.intersect(ray, kInfinity, hit, counters));
            const Vec3 p = ray.at(hit.t);
            if (p.z > 0.5) continue;  // the quad itself
            // Towards the light, to the quad's height: texture coordinates there.
            const Vec3 q = p + (kLight - p) * ((kQuadZ - p.z) / (kLight.z - p.z));
            const Real u = q.x - kQuadX, v = q.y + 0.5;
            if (!clearOfEdges(u, v)) continue;
            const bool shadowed = image.at(x, y).r < 0.3f;  // lit: 0.1 + 0.9 cos 45 degrees; shadow: 0.1
            ++compared;
            agree += shadowed == opaqueAt(u, v);
        }
    EXPECT_GT(compared, 1000);
    EXPECT_EQ(agree, compared) << "pixels of the shadow footprint where the shadow follows the mask";
    for (const Framebuffer& other : pictures)
        for (int y = 0; y < settings.height; ++y)
            for (int x = 0; x < settings.width; ++x) ASSERT_EQ(other.at(x, y), image.at(x, y)) << x << "," << y;
    std::filesystem::remove(path);
}

TEST(Cutout, CameraRaysSeeThroughMaskedTexels) {
    const std::string path = testing::TempDir() + "/cutout-see-through.png";
    writeMask(path, 1);  // a grey mask, as OBJ's map_d: its only channel is the alpha
    Scene scene = floorUnderCutout(path);
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    const std::unique_ptr<MaterialFilter> filter = materialFilter({scene, &images});
    ASSERT_TRUE(filter);
    const std::unique_ptr<Accelerator> accel = buildAccelerator(scene.primitives, AccelSettings{});
    accel->setHitFilter(filter.get());
    const Vec3 above{0, 0, 10};
    int compared = 0, agree = 0;
    for (Real u = Real(0.01); u < 1; u += Real(0.02))
        for (Real v = Real(0.01); v < 1; v += Real(0.02)) {
            if (!clearOfEdges(u, v)) continue;
            const Vec3 target{kQuadX + u, v - Real(0.5), kQuadZ};
            const Ray ray{above, normalize(target - above)};
            Hit hit;
            RayCounters counters;
            ASSERT_TRUE(accel->intersect(ray, kInfinity, hit, counters));
            const bool onQuad = ray.at(hit.t).z > 1;
            ++compared;
            agree += onQuad == opaqueAt(u, v);
            EXPECT_EQ(accel->occluded(ray, length(target - above) + 1, counters), opaqueAt(u, v));
        }
    EXPECT_GT(compared, 500);
    EXPECT_EQ(agree, compared);
    std::filesystem::remove(path);
}

TEST(Cutout, AMaterialThatCannotCutOutAddsNoFilter) {
    const std::string path = testing::TempDir() + "/cutout-opaque.png";
    writeMask(path, 3);  // RGB: no alpha, so an alpha read from it (not a mask) is 1 everywhere
    Scene scene = floorUnderCutout(path);
    scene.materials[1].colorTexture = 0;  // the alpha is the colour texture's: glTF's base colour
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    EXPECT_FALSE(materialFilter({scene, &images}));
    scene.materials[1].opacity.alpha = 0.25f;  // below the cut-off everywhere
    EXPECT_TRUE(materialFilter({scene, &images}));
    std::filesystem::remove(path);
}

TEST(TextureFiles, AlphaIsTheAlphaChannelOrTheGreyOfAMask) {
    const std::string dir = testing::TempDir();
    writeMask(dir + "/alpha4.png", 4);
    writeMask(dir + "/alpha1.png", 1);
    writeMask(dir + "/alpha3.png", 3);
    Scene scene;
    for (const char* name : {"alpha4", "alpha1", "alpha3"})
        scene.textures.push_back({.name = name, .path = dir + "/" + name + ".png"});
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    const float clear = (kCell + 0.5f) / kSize, opaque = 0.5f / kSize;  // texel centres
    for (bool mask : {false, true}) {
        EXPECT_EQ(images.alpha(0, clear, opaque, mask), 0.0f);
        EXPECT_EQ(images.alpha(0, opaque, opaque, mask), 1.0f);
        EXPECT_TRUE(images.hasAlpha(0, mask));
    }
    EXPECT_EQ(images.alpha(1, clear, opaque, true), 0.0f);
    EXPECT_EQ(images.alpha(1, clear, opaque, false), 1.0f);
    EXPECT_FALSE(images.hasAlpha(1, false));
    EXPECT_EQ(images.alpha(2, clear, opaque, true), 1.0f);  // RGB: its first channel is white
    EXPECT_FALSE(images.hasAlpha(2, false));
    for (const char* name : {"alpha4", "alpha1", "alpha3"}) std::filesystem::remove(dir + "/" + name + ".png");
}

// Cut-outs read the finest level with one bilinear probe (no MIP footprint: traversal has no
// differentials): across the edge of a cell the alpha blends the two nearest texels.
TEST(TextureFiles, AlphaBlendsTheTwoNearestTexelsOfTheFinestLevel) {
    const std::string path = testing::TempDir() + "/alpha-blend.png";
    writeMask(path, 4);
    Scene scene;
    scene.textures.push_back({.name = "mask", .path = path});
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    const float row = 0.5f / kSize;  // a row of texel centres; texel kCell - 1 is opaque, texel kCell clear
    EXPECT_EQ(images.alpha(0, float(kCell) / kSize, row, false), 0.5f);
    EXPECT_EQ(images.alpha(0, (kCell + 0.25f) / kSize, row, false), 0.25f);  // a quarter of the way past the edge
    EXPECT_EQ(images.alpha(0, (kCell - 0.25f) / kSize, row, false), 0.75f);
    std::filesystem::remove(path);
}

// Each thread remembers the last alpha asked for (a ray's traversal often asks again for the hit it
// just tested), per TextureFiles: two alive at once, asked in turn for the same texture index,
// channel and coordinates, each answer from its own picture.
TEST(TextureFiles, AlphaAskedAgainIsItsOwnPicturesForEachTextureFiles) {
    const std::string dir = testing::TempDir();
    writeMask(dir + "/alpha-grey.png", 1);  // clear cells: 0 in its only channel
    writeMask(dir + "/alpha-rgb.png", 3);   // its first channel white everywhere
    const auto scene = [&](const char* name) {
        Scene s;
        s.textures.push_back({.name = name, .path = dir + "/" + name + ".png"});
        return s;
    };
    const Scene grey = scene("alpha-grey"), rgb = scene("alpha-rgb");
    std::vector<std::string> warnings;
    const TextureFiles greyImages(grey, warnings), rgbImages(rgb, warnings);
    const float clear = (kCell + 0.5f) / kSize, row = 0.5f / kSize;
    for (int turn = 0; turn < 2; ++turn) {
        EXPECT_EQ(greyImages.alpha(0, clear, row, true), 0.0f);
        EXPECT_EQ(greyImages.alpha(0, clear, row, true), 0.0f);  // asked again
        EXPECT_EQ(rgbImages.alpha(0, clear, row, true), 1.0f);
    }
    for (const char* name : {"alpha-grey", "alpha-rgb"}) std::filesystem::remove(dir + "/" + name + ".png");
}
