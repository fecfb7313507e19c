// Names safe as identifiers and file names, unique within their table, by one rule for the
// importers and the scene writer (scene/unique_names.*).
#include <gtest/gtest.h>

#include "scene/unique_names.h"

namespace rt {
namespace {

TEST(SceneNames, UnsafeCharactersAndALeadingDotBecomeUnderscores) {
    EXPECT_EQ(safeName("Wheel-2.left_front"), "Wheel-2.left_front");
    EXPECT_EQ(safeName("../etc/passwd"), "_._etc_passwd");
    EXPECT_EQ(safeName("a b<c>\"d\""), "a_b_c__d_");
    EXPECT_EQ(safeName("."), "_");
    EXPECT_EQ(safeName(""), "");
}

TEST(SceneNames, TakenNamesGetTheFirstFreeNumber) {
    NameTable names;
    EXPECT_EQ(names.claim("Wheel", "mesh0"), "Wheel");
    EXPECT_EQ(names.claim("Wheel", "mesh1"), "Wheel_2");
    EXPECT_EQ(names.claim("Wheel_3", "mesh2"), "Wheel_3");
    EXPECT_EQ(names.claim("Wheel", "mesh3"), "Wheel_4");
    EXPECT_EQ(names.claim("wheel", "mesh4"), "wheel");
    EXPECT_EQ(names.claim("", "mesh5"), "mesh5");
    EXPECT_EQ(names.claim("", "mesh5"), "mesh5_2");
}

TEST(SceneNames, ACaselessTableTellsNamesApartAsLowerCase) {
    NameTable files(true);
    EXPECT_EQ(files.claim("Wheel", "model"), "Wheel");
    EXPECT_EQ(files.claim("wheel", "model"), "wheel_2");
    EXPECT_EQ(files.claim("WHEEL_2", "model"), "WHEEL_2_2");
}

}  // namespace
}  // namespace rt
