#include "io/base64.h"

#include <gtest/gtest.h>

using namespace rt;

namespace {

std::vector<std::uint8_t> bytesOf(std::string_view s) { return {s.begin(), s.end()}; }

std::optional<std::vector<std::uint8_t>> decode(std::string_view text) {
    std::size_t at = 0;
    return decodeBase64(text, at);
}

std::size_t errorAt(std::string_view text) {
    std::size_t at = 12345;
    EXPECT_FALSE(decodeBase64(text, at)) << text;
    return at;
}

}  // namespace

TEST(SceneBase64, Rfc4648TestVectors) {
    const std::pair<const char*, const char*> vectors[] = {{"", ""},
                                                           {"f", "Zg=="},
                                                           {"fo", "Zm8="},
                                                           {"foo", "Zm9v"},
                                                           {"foob", "Zm9vYg=="},
                                                           {"fooba", "Zm9vYmE="},
                                                           {"foobar", "Zm9vYmFy"}};
    for (const auto& [plain, encoded] : vectors) {
        EXPECT_EQ(encodeBase64(bytesOf(plain)), encoded);
        EXPECT_EQ(decode(encoded), bytesOf(plain)) << encoded;
    }
}

TEST(SceneBase64, AllByteValuesRoundTripWithLineBreaks) {
    std::vector<std::uint8_t> bytes;
    for (int i = 0; i < 256 * 3 + 1; ++i) bytes.push_back(std::uint8_t(i * 7 + i / 256));
    const std::string text = encodeBase64(bytes, 76);
    EXPECT_EQ(text.find('\n'), 76u);
    EXPECT_EQ(decode(text), bytes);
    EXPECT_EQ(decode("  Zm9v\r\n\tYmFy \n"), bytesOf("foobar"));  // whitespace anywhere
}

TEST(SceneBase64, MalformedTextNamesTheBadCharacter) {
    EXPECT_EQ(errorAt("Zm9v*mFy"), 4u);  // not in the alphabet
    EXPECT_EQ(errorAt("Zg==Zm8="), 4u);  // data after the padding
    EXPECT_EQ(errorAt("Z==="), 1u);      // padding too early
    EXPECT_EQ(errorAt("Zm9=v"), 4u);     // a digit after '='
    EXPECT_EQ(errorAt("Zm9vY"), 5u);     // incomplete group: the end of the text
}
