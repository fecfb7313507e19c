// ASCII lower case for names and extensions (core/text.h).
#include <gtest/gtest.h>

#include "core/text.h"

namespace rt {
namespace {

TEST(CoreText, LowerCaseTurnsOnlyAsciiLetters) {
    EXPECT_EQ(lowerCase("RAW 3ds_X-1"), "raw 3ds_x-1");
    EXPECT_EQ(lowerCase("\xC3\x89t\xC3\xA9"), "\xC3\x89t\xC3\xA9");  // UTF-8 bytes stay as they are
}

TEST(CoreText, LowerCaseExtensionKeepsTheDotOfTheLastPart) {
    EXPECT_EQ(lowerCaseExtension("models/Duck.GLTF"), ".gltf");
    EXPECT_EQ(lowerCaseExtension("a.tar.GZ"), ".gz");
    EXPECT_EQ(lowerCaseExtension("Makefile"), "");
    EXPECT_EQ(lowerCaseExtension("dir.v2/noext"), "");
}

}  // namespace
}  // namespace rt
