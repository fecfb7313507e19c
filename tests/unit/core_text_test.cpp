// ASCII lower case for names and extensions, numbers in option values, names near a typo (core/text.h).
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

TEST(CoreText, ParseSeparatedReadsExactlyTheNumbersAsked) {
    EXPECT_EQ((parseSeparated<double, 3>("1,-2.5,3e2", ",")), (std::array<double, 3>{1, -2.5, 300}));
    EXPECT_EQ((parseSeparated<int, 2>("4x3", "x")), (std::array<int, 2>{4, 3}));
    EXPECT_EQ((parseSeparated<int, 2>("-1..12", "..")), (std::array<int, 2>{-1, 12}));
    EXPECT_EQ((parseSeparated<int, 1>("7", "..")), (std::array<int, 1>{7}));
    for (const char* bad : {"1,2", "1,2,3,4", "1,,3", ",2,3", "1,2,", "1, 2,3", " 1,2,3", "+1,2,3", "1,2,3x", "a,b,c"})
        EXPECT_FALSE((parseSeparated<double, 3>(bad, ","))) << bad;
    for (const char* bad : {"1.5/2", "1/", "/2", "1/2/3", "99999999999/1", "1-2"})
        EXPECT_FALSE((parseSeparated<int, 2>(bad, "/"))) << bad;
    EXPECT_FALSE((parseSeparated<int, 1>("1..2", "..")));
}

TEST(CoreText, EditDistanceCountsSingleCharacterEdits) {
    EXPECT_EQ(editDistance("", ""), 0u);
    EXPECT_EQ(editDistance("width", "width"), 0u);
    EXPECT_EQ(editDistance("", "abc"), 3u);
    EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
    EXPECT_EQ(editDistance("--widht", "--width"), 2u);  // a transposition is two substitutions
    EXPECT_EQ(editDistance("--treads", "--threads"), 1u);
}

TEST(CoreText, NearestNameSuggestsOnlyWhatIsNearEnough) {
    const std::vector<std::string> names{"--width", "--height", "--threads", "--seed"};
    EXPECT_EQ(nearestName("--widht", names), "--width");
    EXPECT_EQ(nearestName("--treads", names), "--threads");
    EXPECT_EQ(nearestName("--heigth", names), "--height");
    EXPECT_FALSE(nearestName("--no-such-option", names));
    EXPECT_FALSE(nearestName("-x", {"-y"}));              // one letter for another is no typo
    EXPECT_EQ(nearestName("--fob", {"--fov"}), "--fov");  // a third of five characters: one edit
}

}  // namespace
}  // namespace rt
