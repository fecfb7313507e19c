// Image textures through OpenImageIO's TextureSystem (libtrace/image/texture_files.*): a
// textured quad seen head-on reproduces its picture, wrap modes, and a missing file.
#include "image/texture_files.h"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "../unit/render_test_scenes.h"
#include "accel/naive.h"
#include "render/renderer.h"

using namespace rt;

namespace {

constexpr int kSize = 16;  // texels a side

// An 8-bit sRGB picture of coloured texels, written to `path`; returns its texels decoded to linear.
std::vector<Color> writePicture(const std::string& path) {
    OIIO::ImageBuf picture(OIIO::ImageSpec(kSize, kSize, 3, OIIO::TypeDesc::UINT8));
    std::vector<Color> linear;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float texel[3] = {float(x) / (kSize - 1), float(y) / (kSize - 1), float((x + y) % 3) / 2};
            picture.setpixel(x, y, texel);
            float stored[3];
            picture.getpixel(x, y, stored);  // as 8 bits hold it
            const auto decode = [](float v) {
                return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            };
            linear.push_back({decode(stored[0]), decode(stored[1]), decode(stored[2])});
        }
    EXPECT_TRUE(picture.write(path));
    return linear;
}

// A unit quad at z = 0 with texture coordinates (0, 0) at its top-left corner, filling a
// kSize-pixel square picture seen head-on: each pixel centre falls on a texel centre. Only
// the emission shows (black, unlit material), so the picture is the texture itself.
Scene texturedQuad(const std::string& picture) {
    Scene s;
    s.camera.origin = {0.5, 0.5, 2};  // looking down -z: +x to the right, +y up
    s.camera.destination = {0.5, 0.5, 0};
    s.camera.focalDistance =
        2 * kReferenceWidth;  // f is in pixels of an 800-wide picture: one unit fills the width at distance 2
    s.textures.push_back({.name = "picture", .path = picture});
    Material m{.name = "screen", .color = {0, 0, 0}, .ambient = 0, .diffuse = 0, .emission = {1, 1, 1}};
    m.emissionTexture = 0;
    s.materials.push_back(m);
    Model quad;
    quad.triangleVertices = {0, 1, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 0};
    quad.vertexUvs = {0, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1};
    s.models.push_back(quad);
    s.instances.push_back({0, 0, Transform()});
    s.flatten();
    return s;
}

}  // namespace

TEST(TextureFiles, ATexturedQuadSeenHeadOnReproducesItsPicture) {
    const std::string dir = testing::TempDir();
    const std::string path = dir + "/texels.png";
    const std::vector<Color> texels = writePicture(path);
    const Scene scene = texturedQuad(path);
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    EXPECT_TRUE(warnings.empty());
    const NaiveAccelerator accel(scene.primitives);
    RenderSettings settings = test::picture(kSize, kSize);
    RenderStats stats;
    const Framebuffer image = render(scene, accel, settings, stats, {}, &images);
    double squaredError = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Color got = image.at(x, y), want = texels[std::size_t(y * kSize + x)];
            for (float d : {got.r - want.r, got.g - want.g, got.b - want.b}) squaredError += double(d) * d;
        }
    const double psnr = 10 * std::log10(1 / (squaredError / (3.0 * kSize * kSize)));
    EXPECT_GE(psnr, 40) << "PSNR in dB";
    std::filesystem::remove(path);
}

TEST(TextureFiles, WrapModesRepeatClampAndMirror) {
    const std::string path = testing::TempDir() + "/wrap.png";
    const std::vector<Color> texels = writePicture(path);
    Scene scene;
    for (Texture::Wrap w : {Texture::Wrap::Repeat, Texture::Wrap::Clamp, Texture::Wrap::Mirror})
        scene.textures.push_back({.name = "t", .path = path, .wrapS = w, .wrapT = w});
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    const float texel = 1.0f / kSize;
    const auto near = [](const Color& a, const Color& b) {
        return std::abs(a.r - b.r) < 1e-3f && std::abs(a.g - b.g) < 1e-3f && std::abs(a.b - b.b) < 1e-3f;
    };
    // Half a texel past the right edge: repeat reads the first column, clamp and mirror the last.
    const float s = 1 + texel / 2, t = texel / 2;
    EXPECT_TRUE(near(images.lookup(0, s, t), texels[0]));
    EXPECT_TRUE(near(images.lookup(1, s, t), texels[kSize - 1]));
    EXPECT_TRUE(near(images.lookup(2, s, t), texels[kSize - 1]));
    // 1.5 texels past: clamp still the last column, mirror the one before it.
    EXPECT_TRUE(near(images.lookup(2, 1 + 1.5f * texel, t), texels[kSize - 2]));
    std::filesystem::remove(path);
}

TEST(TextureFiles, AMissingPictureIsAWarningAndWhite) {
    Scene scene;
    scene.textures.push_back({.name = "gone", .path = testing::TempDir() + "/no-such-picture.png"});
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("texture 'gone': cannot read"), std::string::npos) << warnings[0];
    EXPECT_EQ(images.lookup(0, 0.5f, 0.5f), (Color{1, 1, 1}));
}
