// OpenEXR headers checked before OpenImageIO opens a texture (libtrace/image/exr_header.*): an
// attribute that declares more bytes than its file holds is refused, so OpenEXR never allocates it.
#include "image/exr_header.h"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "image/image_header.h"
#include "image/texture_files.h"

using namespace rt;

namespace {

// A 4 x 4 OpenEXR file with a "comments" string attribute; returns its bytes.
std::vector<std::uint8_t> writeExr(const std::string& path) {
    OIIO::ImageSpec spec(4, 4, 3, OIIO::TypeDesc::HALF);
    spec.attribute("ImageDescription", "a comment");  // OpenEXR's "comments"
    OIIO::ImageBuf picture(spec);
    EXPECT_TRUE(picture.write(path));
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// The bytes with the "comments" attribute's size field set to `declared` (little-endian).
std::vector<std::uint8_t> withCommentSize(std::vector<std::uint8_t> bytes, std::uint32_t declared) {
    const std::string key("comments\0string\0", 16);
    const auto at = std::search(bytes.begin(), bytes.end(), key.begin(), key.end());
    EXPECT_NE(at, bytes.end());
    for (int i = 0; i < 4; ++i) *(at + std::ptrdiff_t(key.size() + i)) = std::uint8_t(declared >> (8 * i));
    return bytes;
}

}  // namespace

TEST(ExrHeader, AWellFormedFileAndOtherFormatsPass) {
    const std::string path = testing::TempDir() + "/exr-header-good.exr";
    writeExr(path);
    EXPECT_EQ(checkImageHeader(path).refusal, std::nullopt);
    const std::string png = testing::TempDir() + "/exr-header-other.png";
    EXPECT_TRUE(OIIO::ImageBuf(OIIO::ImageSpec(2, 2, 3, OIIO::TypeDesc::UINT8)).write(png));
    EXPECT_EQ(checkImageHeader(png).refusal, std::nullopt);
}

// The fuzzer's input (fuzz/corpus/image_texture/exr_attribute_declares_1.8_gb) in a file of the
// test's own making: 1,852,964,949 bytes declared for a string in a file of a few hundred.
TEST(ExrHeader, AnAttributeLargerThanTheFileIsRefused) {
    const std::string path = testing::TempDir() + "/exr-header-bad.exr";
    writeBytes(path, withCommentSize(writeExr(path), 0x6e720055));
    const std::optional<std::string> why = checkImageHeader(path).refusal;
    ASSERT_TRUE(why);
    EXPECT_NE(why->find("attribute 'comments' declares 1852964949 bytes"), std::string::npos) << *why;
}

TEST(ExrHeader, AHeaderCutShortIsRefused) {
    std::vector<std::uint8_t> bytes = writeExr(testing::TempDir() + "/exr-header-cut.exr");
    bytes.resize(30);  // inside the first attribute
    const ByteReader read = [&](std::uint64_t offset, std::size_t count, std::uint8_t* out) {
        if (offset > bytes.size() || count > bytes.size() - offset) return false;
        std::memcpy(out, bytes.data() + offset, count);
        return true;
    };
    EXPECT_TRUE(exrHeaderProblem(read, bytes.size()));
}

TEST(ExrHeader, ATextureWithSuchAHeaderIsAnInputError) {
    const std::string path = testing::TempDir() + "/exr-header-texture.exr";
    writeBytes(path, withCommentSize(writeExr(path), 0x7ffffff0));
    Scene scene;
    scene.textures.push_back({.name = "huge", .path = path});
    std::vector<std::string> warnings;
    try {
        const TextureFiles images(scene, warnings);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("texture 'huge'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("declares 2147483632 bytes"), std::string::npos) << e.what();
    }
}
