#include "image/image_output.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"

using namespace rt;
namespace fs = std::filesystem;

namespace {

class ImageOutputTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("rt_image_output_test_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string file(const std::string& name) const { return (dir_ / name).string(); }
    std::size_t filesInDir() const { return std::size_t(std::distance(fs::directory_iterator(dir_), {})); }

    static ImageOutputSettings settings(ImageFormat format, const std::string& path) {
        ImageOutputSettings s;
        s.format = format;
        s.path = path;
        s.color.configPath = RT_SOURCE_DIR "/config/ocio/config.ocio";
        return s;
    }
    static ImageMetadata metadata() { return {"rt-render test", "scenes/test.xml", 16, 1.5}; }

    fs::path dir_;
};

// A 4x2 image: a horizontal ramp, middle grey at (1, 0).
Framebuffer ramp(const PixelWindow& w = {0, 0, 4, 2}, int fullWidth = 4, int fullHeight = 2) {
    Framebuffer fb(fullWidth, fullHeight, w);
    for (int y = w.y0; y < w.y1; ++y)
        for (int x = w.x0; x < w.x1; ++x) fb.at(x, y) = {0.06f * float(x) + 0.12f, 0.18f, float(y)};
    return fb;
}

std::vector<float> readPixels(const std::string& path, OIIO::ImageSpec& spec) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << OIIO::geterror();
    if (!in) return {};
    spec = in->spec();
    std::vector<float> px(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
    return px;
}

}  // namespace

TEST_F(ImageOutputTest, FormatsByNameAndExtension) {
    EXPECT_EQ(parseImageFormat("exr"), ImageFormat::Exr);
    EXPECT_EQ(parseImageFormat("text"), ImageFormat::Text);
    EXPECT_EQ(parseImageFormat("jpeg"), ImageFormat::Jpeg);
    EXPECT_EQ(parseImageFormat("jpg"), std::nullopt);
    EXPECT_EQ(imageFormatFromPath("a.JPEG"), ImageFormat::Jpeg);
    EXPECT_EQ(imageFormatFromPath("a.tiff"), ImageFormat::Tiff);
    EXPECT_EQ(imageFormatFromPath("out/a.PNG"), ImageFormat::Png);
    EXPECT_EQ(imageFormatFromPath("a.tga"), ImageFormat::Tga);
    EXPECT_EQ(imageFormatFromPath("a.txt"), ImageFormat::Text);
    EXPECT_EQ(imageFormatFromPath("a"), std::nullopt);
    EXPECT_STREQ(imageFormatName(ImageFormat::Null), "null");
}

TEST_F(ImageOutputTest, ExtensionPicksTheFormatUnlessOutputTypeNamesOne) {
    using Name = std::optional<std::string>;
    EXPECT_EQ(chooseImageFormat(Name(), Name()), ImageFormat::Null);
    EXPECT_EQ(chooseImageFormat(Name(), Name("a.EXR")), ImageFormat::Exr);
    EXPECT_EQ(chooseImageFormat(Name("png"), Name()), ImageFormat::Png);
    EXPECT_EQ(chooseImageFormat(Name("png"), Name("a.png")), ImageFormat::Png);
    EXPECT_EQ(chooseImageFormat(Name("exr"), Name("-")), ImageFormat::Exr);
    EXPECT_EQ(chooseImageFormat(Name("png"), Name("picture")), ImageFormat::Png);  // no extension: -o says
    // Contradictions and files no writer handles are usage errors.
    EXPECT_THROW(chooseImageFormat(Name("png"), Name("m.exr")), InputError);
    EXPECT_THROW(chooseImageFormat(Name("exr"), Name("m.png")), InputError);
    EXPECT_THROW(chooseImageFormat(Name("null"), Name("m.png")), InputError);
    EXPECT_THROW(chooseImageFormat(Name(), Name("m.bmp")), InputError);
    EXPECT_THROW(chooseImageFormat(Name(), Name("-")), InputError);
    EXPECT_THROW(chooseImageFormat(Name("bmp"), Name()), InputError);
}

TEST_F(ImageOutputTest, OutputTypeWritesFilesWithoutTheExtension) {
    const std::string path = file("picture");
    writeImage(ramp(), settings(ImageFormat::Exr, path), metadata());
    OIIO::ImageSpec spec;
    readPixels(path, spec);
    EXPECT_EQ(spec.format, OIIO::TypeDesc::HALF);
}

TEST_F(ImageOutputTest, ExrKeepsLinearValuesAndMetadata) {
    for (const bool inHalf : {true, false}) {
        ImageOutputSettings s = settings(ImageFormat::Exr, file("a.exr"));
        s.exrPixels = inHalf ? ExrPixelType::Half : ExrPixelType::Float;
        writeImage(ramp(), s, metadata());
        OIIO::ImageSpec spec;
        const std::vector<float> px = readPixels(s.path, spec);
        EXPECT_EQ(spec.format, inHalf ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
        EXPECT_NEAR(px[3], 0.06f + 0.12f, inHalf ? 1e-4 : 0);
        EXPECT_EQ(spec.get_string_attribute("Software"), "rt-render test");
        EXPECT_EQ(spec.get_string_attribute("rt:scene"), "scenes/test.xml");
        EXPECT_EQ(spec.get_string_attribute("rt:colorSpace"), "lin_rec709");
        EXPECT_EQ(spec.get_string_attribute("rt:colorConfig"), s.color.configPath);  // the config used
        EXPECT_EQ(spec.get_int_attribute("rt:samplesPerPixel"), 16);
        EXPECT_FLOAT_EQ(spec.get_float_attribute("rt:renderSeconds"), 1.5f);
    }
}

TEST_F(ImageOutputTest, RegionBecomesTheDataWindow) {
    const std::string path = file("tile.exr");
    writeImage(ramp({2, 1, 5, 3}, 8, 6), settings(ImageFormat::Exr, path), metadata());
    OIIO::ImageSpec spec;
    const std::vector<float> px = readPixels(path, spec);
    EXPECT_EQ(spec.x, 2);
    EXPECT_EQ(spec.y, 1);
    EXPECT_EQ(spec.width, 3);
    EXPECT_EQ(spec.height, 2);
    EXPECT_EQ(spec.full_x, 0);
    EXPECT_EQ(spec.full_width, 8);
    EXPECT_EQ(spec.full_height, 6);
    EXPECT_NEAR(px[0], 0.06f * 2 + 0.12f, 1e-3);  // pixel (2, 1) comes first
}

TEST_F(ImageOutputTest, PngAndTgaGoThroughTheDisplayTransform) {
    for (const auto& [format, name, bits] :
         {std::tuple{ImageFormat::Png, "a.png", 8}, std::tuple{ImageFormat::Png, "b.png", 16},
          std::tuple{ImageFormat::Tga, "c.tga", 8}}) {
        ImageOutputSettings s = settings(format, file(name));
        s.pngBits = bits;
        writeImage(ramp(), s, metadata());
        auto in = OIIO::ImageInput::open(s.path);
        ASSERT_TRUE(in) << OIIO::geterror();
        EXPECT_EQ(in->spec().format, bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
        std::vector<std::uint16_t> px(4 * 2 * 3);
        ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT16, px.data()));
        // Linear 0.18 encodes to sRGB 0.461356: code value 118 of 255, 30235 of 65535.
        const int expected = bits == 16 ? 30235 : 118 * 257;
        EXPECT_EQ(px[3], expected) << name;
        EXPECT_EQ(px[4], expected) << name;
    }
}

// Every format rt writes reads back through OpenImageIO with its size, depth and encoding:
// display-referred ones hold linear 0.18 as sRGB 0.4614, scene-referred ones keep 0.18.
TEST_F(ImageOutputTest, EveryFormatReadsBackWithItsDepthAndEncoding) {
    struct Case {
        ImageFormat format;
        const char* name;
        int tiffBits;
        OIIO::TypeDesc stored;
        bool linear;
        float tolerance;
    };
    // JPEG's chroma subsampling blurs the ramp's blue: only the encoding shows, not the exact value.
    for (const Case& c : {Case{ImageFormat::Jpeg, "a.jpg", 8, OIIO::TypeDesc::UINT8, false, 0.1f},
                          Case{ImageFormat::Tiff, "a.tif", 8, OIIO::TypeDesc::UINT8, false, 0.003f},
                          Case{ImageFormat::Tiff, "b.tiff", 16, OIIO::TypeDesc::UINT16, false, 1e-4f},
                          Case{ImageFormat::Tiff, "c.tif", 32, OIIO::TypeDesc::FLOAT, true, 1e-6f},
                          Case{ImageFormat::Hdr, "a.hdr", 8, OIIO::TypeDesc::FLOAT, true, 0.004f},
                          Case{ImageFormat::Pfm, "a.pfm", 8, OIIO::TypeDesc::FLOAT, true, 1e-6f}}) {
        EXPECT_EQ(imageFormatFromPath(c.name), c.format) << c.name;
        if (!imageFormatWritable(c.format)) {  // refused before rendering, not written wrong
            EXPECT_THROW(chooseImageFormat(std::nullopt, file(c.name)), InputError) << c.name;
            continue;
        }
        ImageOutputSettings s = settings(c.format, file(c.name));
        s.tiffBits = c.tiffBits;
        s.jpegQuality = 100;
        writeImage(ramp(), s, metadata());
        OIIO::ImageSpec spec;
        const std::vector<float> px = readPixels(s.path, spec);
        EXPECT_EQ(spec.width, 4) << c.name;
        EXPECT_EQ(spec.height, 2) << c.name;
        EXPECT_EQ(spec.nchannels, 3) << c.name;
        EXPECT_EQ(spec.format, c.stored) << c.name;
        ASSERT_EQ(px.size(), 24u);
        EXPECT_NEAR(px[4], c.linear ? 0.18f : 0.461356f, c.tolerance) << c.name << ": green of pixel (1, 0)";
        EXPECT_NEAR(px[16], c.linear ? 0.18f : 0.461356f, c.tolerance) << c.name << ": green of pixel (1, 1)";
    }
}

// Two pixels over a coloured background: one all background (alpha 0), one half covered by
// grey 0.8 (its colour the mean of 0.8 and the background).
Framebuffer halfCovered() {
    const Color background{0.2f, 0.4f, 0.6f};
    Framebuffer fb(2, 1, {0, 0, 2, 1}, background);
    fb.at(0, 0) = background;
    fb.alphaAt(0, 0) = 0;
    fb.at(1, 0) = Color{0.4f, 0.4f, 0.4f} + background * 0.5f;
    fb.alphaAt(1, 0) = 0.5f;
    return fb;
}

TEST_F(ImageOutputTest, AlphaIsPremultipliedInExrAndStraightInPng) {
    ImageOutputSettings exr = settings(ImageFormat::Exr, file("a.exr"));
    exr.exrPixels = ExrPixelType::Float;
    exr.alpha = true;
    writeImage(halfCovered(), exr, metadata());
    OIIO::ImageSpec spec;
    std::vector<float> px = readPixels(file("a.exr"), spec);
    ASSERT_EQ(spec.nchannels, 4);
    EXPECT_EQ(spec.alpha_channel, 3);
    const std::vector<float> premultiplied{0, 0, 0, 0, 0.4f, 0.4f, 0.4f, 0.5f};
    for (std::size_t i = 0; i < px.size(); ++i) EXPECT_NEAR(px[i], premultiplied[i], 1e-6f) << i;

    ImageOutputSettings png = settings(ImageFormat::Png, file("a.png"));
    png.color.view = "Raw";  // no display transform: the file holds the linear values
    png.alpha = true;
    writeImage(halfCovered(), png, metadata());
    OIIO::ImageSpec straight;
    straight.attribute("oiio:UnassociatedAlpha", 1);  // read the file's values as they are
    auto in = OIIO::ImageInput::open(file("a.png"), &straight);
    ASSERT_TRUE(in) << OIIO::geterror();
    ASSERT_EQ(in->spec().nchannels, 4);
    px.assign(8, -1);
    ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, px.data()));
    EXPECT_EQ(px[3], 0);
    for (int c = 4; c < 7; ++c) EXPECT_NEAR(px[std::size_t(c)], 0.8f, 1 / 255.0f) << c;
    EXPECT_NEAR(px[7], 0.5f, 1 / 255.0f);

    png.alpha = false;  // over the background, as before alpha existed
    writeImage(halfCovered(), png, metadata());
    px = readPixels(file("a.png"), spec);
    ASSERT_EQ(spec.nchannels, 3);
    EXPECT_NEAR(px[0], 0.2f, 1 / 255.0f);
    EXPECT_NEAR(px[3], 0.5f, 1 / 255.0f);
}

TEST_F(ImageOutputTest, TextIsAsciiArt) {
    Framebuffer fb(3, 2, {0, 0, 3, 2});
    fb.at(1, 0) = {1, 1, 1};
    fb.at(2, 1) = {0.18f, 0.18f, 0.18f};
    const std::string path = file("a.txt");
    writeImage(fb, settings(ImageFormat::Text, path), metadata());
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    EXPECT_EQ(text.str(), " @ \n  =\n");  // black, white; grey 0.46 is the 5th of 10 on " .:-=+*#%@"
}

TEST_F(ImageOutputTest, FailedWritesLeaveTheOldFileAndNoTemporary) {
    const std::string path = file("keep.png");
    std::ofstream(path) << "previous";
    ImageOutputSettings s = settings(ImageFormat::Png, path);
    s.color.view = "NoSuchView";
    EXPECT_THROW(writeImage(ramp(), s, metadata()), InputError);
    s = settings(ImageFormat::Png, file("no/such/dir/a.png"));
    EXPECT_THROW(writeImage(ramp(), s, metadata()), std::runtime_error);
    std::stringstream kept;
    kept << std::ifstream(path).rdbuf();
    EXPECT_EQ(kept.str(), "previous");
    EXPECT_EQ(filesInDir(), 1u);
}

// Every format is checked to the last byte: a full device (a node with /dev/full's numbers)
// is an error naming the file and the reason, and the node is not replaced by a regular file.
TEST_F(ImageOutputTest, AFullDeviceIsAnErrorInEveryFormat) {
    if (::geteuid() != 0) GTEST_SKIP() << "making a device node needs root";
    const std::string full = file("full");
    ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, makedev(1, 7)), 0) << std::strerror(errno);
    for (ImageFormat format : {ImageFormat::Png, ImageFormat::Tga, ImageFormat::Exr, ImageFormat::Text}) {
        try {
            writeImage(ramp(), settings(format, full), metadata());
            ADD_FAILURE() << imageFormatName(format) << ": writing to a full device succeeded";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(full + ": cannot write: No space left on device"), std::string::npos)
                << e.what();
        }
        EXPECT_TRUE(fs::is_character_file(full)) << imageFormatName(format) << " replaced the device";
    }
    EXPECT_EQ(filesInDir(), 1u);
}

TEST_F(ImageOutputTest, NullWritesNothing) {
    writeImage(ramp(), settings(ImageFormat::Null, file("x.png")), metadata());
    EXPECT_EQ(filesInDir(), 0u);
}
