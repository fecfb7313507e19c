// Image textures through OpenImageIO's TextureSystem (libtrace/image/texture_files.*): a
// textured quad seen head-on reproduces its picture, wrap modes, and a missing file.
#include "image/texture_files.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "../unit/render_test_scenes.h"
#include "accel/naive.h"
#include "core/error.h"
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

// The PSNR in dB of texturedQuad's picture rendered with `images` against `texels`.
double quadPsnr(const Scene& scene, const ImageTextures& images, const std::vector<Color>& texels) {
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
    return 10 * std::log10(1 / (squaredError / (3.0 * kSize * kSize)));
}

}  // namespace

TEST(TextureFiles, ATexturedQuadSeenHeadOnReproducesItsPicture) {
    const std::string path = testing::TempDir() + "/texels.png";
    const std::vector<Color> texels = writePicture(path);
    const Scene scene = texturedQuad(path);
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    EXPECT_TRUE(warnings.empty());
    EXPECT_GE(quadPsnr(scene, images, texels), 40) << "PSNR in dB";
    std::filesystem::remove(path);
}

namespace {

// The same lookups without their footprints: the finest level, bilinear (no ray differentials).
class Unfiltered : public ImageTextures {
public:
    Unfiltered(const Scene& scene, const ImageTextures& filtered) : ImageTextures(scene), filtered_(filtered) {}
    Color lookup(std::uint32_t i, const TexCoord& at) const override { return filtered_.lookup(i, {at.s, at.t}); }
    Color data(std::uint32_t i, const TexCoord& at) const override { return filtered_.data(i, {at.s, at.t}); }
    float alpha(std::uint32_t i, float s, float t, bool mask) const override { return filtered_.alpha(i, s, t, mask); }
    bool hasAlpha(std::uint32_t i, bool mask) const override { return filtered_.hasAlpha(i, mask); }

private:
    const ImageTextures& filtered_;
};

// A black and white checker of 8 x 8 squares, 8 texels each, in float (linear: no sRGB
// decoding, whose mip levels would average encoded values), written to `path`.
void writeChecker(const std::string& path) {
    OIIO::ImageBuf picture(OIIO::ImageSpec(64, 64, 1, OIIO::TypeDesc::FLOAT));
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const float v = float((x / 8 + y / 8) % 2);
            picture.setpixel(x, y, &v);
        }
    EXPECT_TRUE(picture.write(path));
}

// A floor 400 units deep, the checker repeated every 4 units (squares of 0.5), seen from one
// unit above it looking towards the horizon: far away hundreds of squares fall in a pixel.
Scene checkerFloor(const std::string& checker) {
    Scene s;
    s.camera.origin = {0, 1, 2};
    s.camera.destination = {0, 0.4, -10};
    s.camera.fovDegrees = 60;
    s.textures.push_back({.name = "checker", .path = checker});
    Material m{.name = "floor", .color = {0, 0, 0}, .ambient = 0, .diffuse = 0, .emission = {1, 1, 1}};
    m.emissionTexture = 0;
    s.materials.push_back(m);
    Model floor;
    const float x = 100, zNear = 10, zFar = -400;
    floor.triangleVertices = {-x, 0, zNear, x, 0, zNear, x, 0, zFar, -x, 0, zNear, x, 0, zFar, -x, 0, zFar};
    for (std::size_t i = 0; i < floor.triangleVertices.size(); i += 3)
        for (std::size_t a : {std::size_t(0), std::size_t(2)})
            floor.vertexUvs.push_back(floor.triangleVertices[i + a] / 4);
    s.models.push_back(floor);
    s.instances.push_back({0, 0, Transform()});
    s.flatten();
    return s;
}

// `scene` at 96 x 64 three ways: 64 point samples a pixel (the reference), one sample a pixel
// filtered over its footprint by `filtered`, and one point sample.
struct ThreeRenders {
    Framebuffer reference, filtered, pointSampled;
};

ThreeRenders renderThreeWays(const Scene& scene, const ImageTextures& filtered) {
    const Unfiltered unfiltered(scene, filtered);
    const NaiveAccelerator accel(scene.primitives);
    RenderStats stats;
    RenderSettings settings = test::picture(96, 64);
    settings.pixelSamples = 64;
    Framebuffer reference = render(scene, accel, settings, stats, {}, &unfiltered);
    settings.pixelSamples = 1;
    Framebuffer withFootprints = render(scene, accel, settings, stats, {}, &filtered);
    Framebuffer pointSampled = render(scene, accel, settings, stats, {}, &unfiltered);
    return {std::move(reference), std::move(withFootprints), std::move(pointSampled)};
}

}  // namespace

// Ray differentials (render/ray_differential.h): one filtered sample a pixel comes close to
// 64 point samples, where one point sample a pixel shimmers (measured: RMS 0.047 against 0.22 with
// an anisotropy of at most 8; OpenImageIO's default of 32 came to 0.050).
TEST(TextureFiles, RayDifferentialsFilterADistantCheckerFloor) {
    const std::string path = testing::TempDir() + "/checker.exr";
    writeChecker(path);
    const Scene scene = checkerFloor(path);
    std::vector<std::string> warnings;
    const TextureFiles filtered(scene, warnings);
    const ThreeRenders three = renderThreeWays(scene, filtered);
    const double errorWith = test::rmsDifference(three.filtered, three.reference);
    const double errorWithout = test::rmsDifference(three.pointSampled, three.reference);
    EXPECT_LT(errorWith, errorWithout / 3) << "RMS error with " << errorWith << ", without " << errorWithout;
    const NaiveAccelerator accel(scene.primitives);
    RenderStats stats;
    RenderSettings settings = test::picture(96, 64);
    settings.threads = 1;
    settings.region = PixelWindow{10, 5, 70, 50};
    const Framebuffer oneThread = render(scene, accel, settings, stats, {}, &filtered);
    for (int y = 5; y < 50; ++y)
        for (int x = 10; x < 70; ++x) ASSERT_EQ(oneThread.at(x, y), three.filtered.at(x, y)) << x << "," << y;
    std::filesystem::remove(path);
}

// A ray cone after a reflection takes fewer probes than a camera ray (render/ray_differential.h):
// the checker, a ceiling seen in a mirror floor towards the horizon, still comes close to 64
// point samples, where one point sample a pixel shimmers (measured: RMS 0.034 against 0.30 with
// an anisotropy of 3, 0.049 with float geometry; 4 came to 0.049, 2 to 0.090, trilinear, one
// probe, to 0.110).
TEST(TextureFiles, ACheckerSeenInAMirrorIsFilteredToo) {
    const std::string path = testing::TempDir() + "/checker-in-mirror.exr";
    writeChecker(path);
    Scene scene = checkerFloor(path);
    for (Model& model : scene.models)  // the floor lifted to a ceiling at y = 2
        for (std::size_t i = 1; i < model.triangleVertices.size(); i += 3) model.triangleVertices[i] = 2;
    const auto mirror = test::addMaterial(scene, {.name = "mirror", .ambient = 0, .diffuse = 0, .reflection = 1});
    test::addQuad(scene, {-100, 0, 10}, {100, 0, 10}, {100, 0, -400}, {-100, 0, -400}, mirror);
    scene.flatten();
    std::vector<std::string> warnings;
    const TextureFiles filtered(scene, warnings);
    const ThreeRenders three = renderThreeWays(scene, filtered);
    const Framebuffer& reference = three.reference;
    // The rows below the horizon, where the camera sees the mirror.
    const auto mirrorError = [&](const Framebuffer& image) {
        double sum = 0;
        int n = 0;
        for (int y = 40; y < 64; ++y)
            for (int x = 0; x < 96; ++x, ++n) {
                const double d = double(image.at(x, y).g) - reference.at(x, y).g;
                sum += d * d;
            }
        return std::sqrt(sum / n);
    };
    EXPECT_GT(reference.at(48, 45).g + reference.at(48, 60).g, 0) << "the checker is seen in the mirror";
    const double errorWith = mirrorError(three.filtered), errorWithout = mirrorError(three.pointSampled);
    EXPECT_LT(errorWith, errorWithout / 5) << "RMS error with " << errorWith << ", without " << errorWithout;
    std::filesystem::remove(path);
}

// Without distributed ray tracing rough glass sends one ray, whose texture footprint widens by
// the lobe's sigma: the checker behind a frosted pane blurs (render/ray_differential.h).
TEST(TextureFiles, RoughGlassWidensTheFootprintOfWhatIsSeenThroughIt) {
    const std::string path = testing::TempDir() + "/checker-behind-glass.exr";
    writeChecker(path);
    const auto contrastThrough = [&](float spread) {
        Scene scene = checkerFloor(path);
        Material pane{.name = "glass", .ambient = 0, .diffuse = 0, .spread = spread};
        pane.transmission = {.weight = 1, .ior = 1.5f};
        scene.looseObjects.add<Sphere>({{0, 0.25, -2}, 0.5}, test::addMaterial(scene, pane));
        scene.flatten();
        std::vector<std::string> warnings;
        const TextureFiles images(scene, warnings);
        const NaiveAccelerator accel(scene.primitives);
        RenderStats stats;
        const Framebuffer image = render(scene, accel, test::picture(96, 64), stats, {}, &images);
        double sum = 0, squares = 0;
        int n = 0;
        for (int y = 35; y < 44; ++y)  // inside the ball
            for (int x = 43; x < 53; ++x, ++n) {
                sum += image.at(x, y).g;
                squares += double(image.at(x, y).g) * image.at(x, y).g;
            }
        return std::sqrt(squares / n - (sum / n) * (sum / n));
    };
    const double sharp = contrastThrough(0), frosted = contrastThrough(0.3f);
    EXPECT_GT(sharp, 0.2);
    EXPECT_LT(frosted, sharp / 3) << "standard deviation: sharp " << sharp << ", frosted " << frosted;
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
    EXPECT_TRUE(near(images.lookup(0, {s, t}), texels[0]));
    EXPECT_TRUE(near(images.lookup(1, {s, t}), texels[kSize - 1]));
    EXPECT_TRUE(near(images.lookup(2, {s, t}), texels[kSize - 1]));
    // 1.5 texels past: clamp still the last column, mirror the one before it.
    EXPECT_TRUE(near(images.lookup(2, {1 + 1.5f * texel, t}), texels[kSize - 2]));
    std::filesystem::remove(path);
}

TEST(TextureFiles, AMissingPictureIsAWarningAndWhite) {
    Scene scene;
    const std::string path = testing::TempDir() + "/no-such-picture.png";
    scene.textures.push_back({.name = "gone", .path = path});
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].rfind("texture file " + path + ": cannot read it (", 0), 0u) << warnings[0];
    EXPECT_EQ(images.lookup(0, {0.5f, 0.5f}), (Color{1, 1, 1}));
}

// An OBJ's map named by several materials is several textures of one file: one warning, of one
// line (OpenImageIO's error text has a second line), not one per texture.
TEST(TextureFiles, AMissingPictureUsedThriceIsOneWarningOfOneLine) {
    Scene scene;
    const std::string path = testing::TempDir() + "/no-such-picture-either.jpg";
    for (const char* name : {"a", "b", "c"}) scene.textures.push_back({.name = name, .path = path});
    scene.textures.push_back({.name = "d", .path = testing::TempDir() + "/nor-this.jpg"});
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings, {.txCache = "off"});
    ASSERT_EQ(warnings.size(), 2u);
    for (const std::string& warning : warnings) EXPECT_EQ(warning.find('\n'), std::string::npos) << warning;
    EXPECT_NE(warnings[0].find(path), std::string::npos) << warnings[0];
    for (std::uint32_t i = 0; i < 4; ++i) EXPECT_EQ(images.lookup(i, {0.5f, 0.5f}), (Color{1, 1, 1}));
}

// OpenImageIO makes an untiled image's MIP levels at its display window's size: a 4 x 4 EXR
// displayed at 257 x 16,795,137 (found by fuzz_image_texture) asked for 2 GB at the first lookup.
TEST(TextureFiles, AnUntiledPictureOfAHugeDisplayWindowIsAnInputError) {
    const std::string path = testing::TempDir() + "/huge-display-window.exr";
    OIIO::ImageSpec spec(4, 4, 4, OIIO::TypeDesc::HALF);
    spec.full_width = 257;
    spec.full_height = 16795137;
    ASSERT_TRUE(OIIO::ImageBuf(spec).write(path));
    Scene scene;
    scene.textures.push_back({.name = "tall", .path = path});
    std::vector<std::string> warnings;
    try {
        const TextureFiles images(scene, warnings);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(
            std::string(e.what()).find("4 x 4 pixels displayed at 257 x 16795137 of 4 channels, 32.2 GiB decoded, "
                                       "more than the 1.0 GiB an image may take"),
            std::string::npos)
            << e.what();
    }
}

// ---- Tiled copies (image/tiled_textures.h) -------------------------------------------------

namespace {

// An empty folder for a test's tx cache (not made: TextureFiles makes it).
std::string freshFolder(const std::string& name) {
    const std::string folder = testing::TempDir() + "/" + name;
    std::filesystem::remove_all(folder);
    return folder;
}

// The copies in the tx cache `folder`, sorted; none if it does not exist.
std::vector<std::filesystem::path> copiesIn(const std::string& folder) {
    std::vector<std::filesystem::path> copies;
    const std::filesystem::path own = std::filesystem::path(folder) / kTxCopiesFolder;
    if (std::filesystem::is_directory(own))
        for (const auto& entry : std::filesystem::directory_iterator(own))
            if (!entry.path().filename().string().starts_with(".")) copies.push_back(entry.path());  // not .lock
    std::sort(copies.begin(), copies.end());
    return copies;
}

}  // namespace

TEST(TextureFiles, AnUntiledPictureIsReadThroughATiledCopyMadeOnceAndReused) {
    const std::string folder = freshFolder("tx-reused"), path = testing::TempDir() + "/tx-reused.png";
    const std::vector<Color> texels = writePicture(path);
    const Scene scene = texturedQuad(path);
    std::vector<std::string> warnings;
    {
        const TextureFiles images(scene, warnings, {.txCache = folder});
        EXPECT_GE(quadPsnr(scene, images, texels), 40) << "PSNR in dB";
    }
    EXPECT_TRUE(warnings.empty());
    const std::vector<std::filesystem::path> copies = copiesIn(folder);
    ASSERT_EQ(copies.size(), 1u);
    OIIO::ImageBuf copy(copies[0].string());
    ASSERT_TRUE(copy.init_spec(copies[0].string(), 0, 0));
    EXPECT_GT(copy.spec().tile_width, 0);
    EXPECT_EQ(copy.nmiplevels(), 5);  // 16, 8, 4, 2 and 1 texels a side
    // Uncompressed: a tile read inflates nothing (docs/benchmarks.md, "Textures").
    EXPECT_EQ(copy.spec().get_string_attribute("compression"), "none");
    // Dated in the past, so that a rewrite within the clock's resolution would show too.
    const auto past = std::filesystem::last_write_time(copies[0]) - std::chrono::hours(1);
    std::filesystem::last_write_time(copies[0], past);
    {
        const TextureFiles again(scene, warnings, {.txCache = folder});
        EXPECT_GE(quadPsnr(scene, again, texels), 40) << "PSNR in dB";
    }
    EXPECT_EQ(copiesIn(folder), copies);
    EXPECT_EQ(std::filesystem::last_write_time(copies[0]), past) << "the copy was made again";
    std::filesystem::remove(path);
}

TEST(TextureFiles, AChangedPictureGetsANewCopy) {
    const std::string folder = freshFolder("tx-changed"), path = testing::TempDir() + "/tx-changed.png";
    writePicture(path);
    Scene scene;
    scene.textures.push_back({.name = "t", .path = path});
    std::vector<std::string> warnings;
    { const TextureFiles before(scene, warnings, {.txCache = folder}); }
    OIIO::ImageBuf grey(OIIO::ImageSpec(kSize, kSize, 3, OIIO::TypeDesc::UINT8));
    OIIO::ImageBufAlgo::fill(grey, {0.5f, 0.5f, 0.5f});
    ASSERT_TRUE(grey.write(path));
    const TextureFiles after(scene, warnings, {.txCache = folder});
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(copiesIn(folder).size(), 2u);
    const float linear = std::pow((128 / 255.0f + 0.055f) / 1.055f, 2.4f);  // 8-bit 0.5 decoded
    EXPECT_NEAR(after.lookup(0, {0.5f, 0.5f}).g, linear, 1e-3f);
    std::filesystem::remove(path);
}

TEST(TextureFiles, AnUnwritableTxCacheIsAWarningAndThePictureIsReadAsItIs) {
    const std::string path = testing::TempDir() + "/tx-unwritable.png";
    const std::vector<Color> texels = writePicture(path);
    const Scene scene = texturedQuad(path);
    std::vector<std::string> warnings;
    const TextureFiles images(scene, warnings, {.txCache = path + "/tx"});  // under a file: no folder, even for root
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("no tiled copy"), std::string::npos) << warnings[0];
    EXPECT_GE(quadPsnr(scene, images, texels), 40) << "PSNR in dB";
    std::filesystem::remove(path);
}

TEST(TextureFiles, AnEmbeddedPictureGetsACopyAndATiledMipMappedFileNone) {
    const std::string folder = freshFolder("tx-embedded"), path = testing::TempDir() + "/tx-embedded.png";
    const std::vector<Color> texels = writePicture(path);
    std::ifstream file(path, std::ios::binary);
    Scene scene = texturedQuad("");
    scene.textures[0].file = "embedded.png";
    scene.textures[0].embedded = std::make_shared<std::vector<std::uint8_t>>(std::istreambuf_iterator<char>(file),
                                                                             std::istreambuf_iterator<char>());
    std::vector<std::string> warnings;
    {
        const TextureFiles images(scene, warnings, {.txCache = folder});
        EXPECT_GE(quadPsnr(scene, images, texels), 40) << "PSNR in dB";
    }
    const std::vector<std::filesystem::path> copies = copiesIn(folder);
    ASSERT_EQ(copies.size(), 1u);
    EXPECT_TRUE(copies[0].filename().string().starts_with("embedded-")) << copies[0];
    // The copy as a scene's own texture is tiled and MIP-mapped already: used as it is.
    const std::string second = freshFolder("tx-of-a-tx");
    const Scene ofTheCopy = texturedQuad(copies[0].string());
    const TextureFiles images(ofTheCopy, warnings, {.txCache = second});
    EXPECT_TRUE(warnings.empty());
    EXPECT_GE(quadPsnr(ofTheCopy, images, texels), 40) << "PSNR in dB";
    EXPECT_TRUE(copiesIn(second).empty());
    std::filesystem::remove(path);
}

// The copy's MIP levels filter as OpenImageIO's own on-the-fly ones: a distant checker floor,
// where the coarse levels show, renders the same within a small difference.
TEST(TextureFiles, ATiledCopyRendersAsTheSourceReadAsItIs) {
    const std::string folder = freshFolder("tx-same"), path = testing::TempDir() + "/tx-same.exr";
    writeChecker(path);
    const Scene scene = checkerFloor(path);
    const NaiveAccelerator accel(scene.primitives);
    RenderStats stats;
    const auto rendered = [&](const std::string& txCache) {
        std::vector<std::string> warnings;
        const TextureFiles images(scene, warnings, {.txCache = txCache});
        EXPECT_TRUE(warnings.empty());
        return render(scene, accel, test::picture(96, 64), stats, {}, &images);
    };
    const Framebuffer asItIs = rendered("off"), throughTheCopy = rendered(folder);
    EXPECT_EQ(copiesIn(folder).size(), 1u);
    const double rms = test::rmsDifference(asItIs, throughTheCopy);
    EXPECT_LT(rms, 0.01) << "RMS difference";
    std::filesystem::remove(path);
}

// A picture of one colour is answered from its copy's one texel (marked by constant_color_detect),
// without OpenImageIO's filter: the values of the picture read as it is, at any footprint; and
// opaque, it cuts nothing out.
TEST(TextureFiles, APictureOfOneColourLooksUpAsBeforeAndOpaqueHasNoAlpha) {
    const std::string folder = freshFolder("tx-constant"), dir = testing::TempDir();
    Scene scene;
    for (const float alpha : {1.0f, 0.4f}) {
        OIIO::ImageBuf picture(OIIO::ImageSpec(kSize, kSize, 4, OIIO::TypeDesc::UINT8));
        OIIO::ImageBufAlgo::fill(picture, {0.3f, 0.6f, 0.9f, alpha});
        const std::string path = dir + "/tx-constant" + std::to_string(scene.textures.size()) + ".png";
        ASSERT_TRUE(picture.write(path));
        scene.textures.push_back({.name = path, .path = path});
    }
    std::vector<std::string> warnings;
    const TextureFiles copied(scene, warnings, {.txCache = folder}), asItIs(scene, warnings, {.txCache = "off"});
    EXPECT_TRUE(warnings.empty());
    for (std::uint32_t i : {0u, 1u})
        for (const TexCoord& at : {TexCoord{0.1f, 0.7f}, TexCoord{0.5f, 0.5f, 0.2f, 0.01f, -0.03f, 0.1f},
                                   TexCoord{0.9f, 0.2f, 0.01f, 0.0f, 0.0f, 0.01f, true}}) {
            // OpenImageIO's filter of equal texels adds rounding error in the last bits.
            const Color a = copied.lookup(i, at), b = asItIs.lookup(i, at), c = copied.data(i, at),
                        d = asItIs.data(i, at);
            for (const auto& [got, want] :
                 {std::pair(a.r, b.r), {a.g, b.g}, {a.b, b.b}, {c.r, d.r}, {c.g, d.g}, {c.b, d.b}})
                EXPECT_NEAR(got, want, 1e-6f);
            EXPECT_NEAR(copied.alpha(i, at.s, at.t, false), asItIs.alpha(i, at.s, at.t, false), 1e-6f);
        }
    EXPECT_FALSE(copied.hasAlpha(0, false));
    EXPECT_TRUE(asItIs.hasAlpha(0, false));  // not known to be opaque: a PNG carries no such mark
    EXPECT_TRUE(copied.hasAlpha(1, false));
    for (const Texture& t : scene.textures) std::filesystem::remove(t.path);
}
