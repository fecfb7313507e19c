#include "image/heatmap_png.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

using namespace rt;
namespace fs = std::filesystem;

// The PNG holds the picture's bytes as they are (no colour transform) and names the
// software the caller gives: the image layer knows no tool.
TEST(HeatmapPng, WritesTheBytesAndTheCallersSoftwareName) {
    const fs::path path = fs::temp_directory_path() / ("rt_heatmap_png_test_" + std::to_string(::getpid()) + ".png");
    RgbImage image(2, 1, {10, 20, 30});
    image.set(1, 0, {200, 100, 50});
    writeHeatmapPng(path.string(), image, "some-tool 9.9");
    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().get_string_attribute("Software"), "some-tool 9.9");
    std::vector<std::uint8_t> bytes(6);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data()));
    EXPECT_EQ(bytes, image.bytes());
    in->close();
    fs::remove(path);
}
