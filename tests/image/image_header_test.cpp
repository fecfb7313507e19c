// The one check every image passes before OpenImageIO reads its pixels (libtrace/image/image_header.*):
// files that are not regular are refused without blocking, headers by what they declare.
#include "image/image_header.h"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

using namespace rt;

namespace {

std::string freshPath(const std::string& name) {
    const std::string path = testing::TempDir() + "/" + name;
    std::filesystem::remove(path);
    return path;
}

// The CRC-32 of PNG chunks (ISO 3309), bit by bit.
std::uint32_t crc32(const std::uint8_t* bytes, std::size_t size) {
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= bytes[i];
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

}  // namespace

TEST(ImageHeader, AFifoIsRefusedWithoutWaitingForAWriter) {
    const std::string path = freshPath("image-header-fifo.png");
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    const ImageHeaderCheck check = checkImageHeader(path);  // a blocking open would never return
    ASSERT_TRUE(check.refusal);
    EXPECT_EQ(*check.refusal, "is a FIFO, not a regular file");
}

TEST(ImageHeader, ADeviceIsRefusedThroughALinkToo) {
    const std::string path = freshPath("image-header-zero.exr");
    std::filesystem::create_symlink("/dev/zero", path);
    for (const std::string& named : {std::string("/dev/urandom"), path}) {
        const ImageHeaderCheck check = checkImageHeader(named);
        ASSERT_TRUE(check.refusal) << named;
        EXPECT_EQ(*check.refusal, "is a character device, not a regular file");
    }
    EXPECT_EQ(*checkImageHeader(testing::TempDir()).refusal, "is a folder, not a regular file");
}

TEST(ImageHeader, AMissingFileIsUnreadableNotRefused) {
    const ImageHeaderCheck check = checkImageHeader(freshPath("image-header-none.png"));
    EXPECT_FALSE(check.refusal);
    ASSERT_TRUE(check.unreadable);
}

TEST(ImageHeader, APictureWithinTheLimitPassesWithItsDecodedSize) {
    const std::string path = freshPath("image-header-small.png");
    ASSERT_TRUE(OIIO::ImageBuf(OIIO::ImageSpec(40, 30, 3, OIIO::TypeDesc::UINT16)).write(path));
    const ImageHeaderCheck check = checkImageHeader(path);
    EXPECT_FALSE(check.refusal);
    EXPECT_FALSE(check.unreadable);
    EXPECT_EQ(check.header.decodedBytes, 40u * 30 * 3 * 2);
    EXPECT_EQ(check.header.channels, 3);
    EXPECT_EQ(check.header.channelBytes, 2);
    EXPECT_FALSE(check.header.floatingPoint);
}

// An embedded PNG whose header says 30000 x 30000 (2.5 GiB decoded) in 60 bytes.
TEST(ImageHeader, AnEmbeddedPictureDeclaringTooManyPixelsIsRefused) {
    const std::string path = freshPath("image-header-embedded.png");
    ASSERT_TRUE(OIIO::ImageBuf(OIIO::ImageSpec(30000, 1, 3, OIIO::TypeDesc::UINT8)).write(path));
    std::vector<std::uint8_t> bytes(std::filesystem::file_size(path));
    FILE* file = std::fopen(path.c_str(), "rb");
    ASSERT_EQ(std::fread(bytes.data(), 1, bytes.size(), file), bytes.size());
    std::fclose(file);
    bytes[22] = 0x75, bytes[23] = 0x30;  // IHDR's height, 1 -> 30000, and the chunk's CRC
    const std::uint32_t crc = crc32(&bytes[12], 17);
    for (int i = 0; i < 4; ++i) bytes[29 + i] = std::uint8_t(crc >> (24 - 8 * i));
    const ImageHeaderCheck check = checkImageHeader(bytes, "picture.png");
    ASSERT_TRUE(check.refusal) << check.unreadable.value_or("");
    EXPECT_EQ(*check.refusal,
              "is 30000 x 30000 pixels of 3 channels, 2.5 GiB decoded, more than the 1.0 GiB an image may take");
}
