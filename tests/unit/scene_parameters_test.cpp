#include "io/parameters.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "io/xml_loader.h"
#include "scene_test_files.h"

using namespace rt;

namespace {

std::string substituted(std::string_view text, const SceneParameters& parameters) {
    std::string missing;
    const std::optional<std::string> out = substituteParameters(text, parameters, missing);
    return out ? *out : "missing " + missing;
}

// A sphere whose radius and colour are parameters, as a sweep would write it.
const std::string kSweep = R"(<scene>
  <camera fov="${fov:-40}"><origin z="-5" /><destination /></camera>
  <materials><material name="m" r="$red" g="0.5" b="0.5" /></materials>
  <objects>
    <sphere r="${radius}" material="m" />
  </objects>
</scene>)";

}  // namespace

TEST(SceneParameters, EveryFormIsReplaced) {
    const SceneParameters p{{"a", "1"}, {"long_name2", "x y"}, {"empty", ""}};
    EXPECT_EQ(substituted("$a", p), "1");
    EXPECT_EQ(substituted("${a}0", p), "10");
    EXPECT_EQ(substituted("$a.5 ${long_name2}", p), "1.5 x y");
    EXPECT_EQ(substituted("${b:-2} ${a:-2} ${empty:-3}", p), "2 1 ");
    EXPECT_EQ(substituted("${b:-}", p), "");
    EXPECT_EQ(substituted("no parameter", p), "no parameter");
}

TEST(SceneParameters, DollarsThatAreNoReferenceStay) {
    const SceneParameters p{{"a", "1"}};
    EXPECT_EQ(substituted("$$a costs 5$", p), "$a costs 5$");
    EXPECT_EQ(substituted("$1 ${} ${a", p), "$1 ${} ${a");
    EXPECT_EQ(substituted("${a:+x}", p), "${a:+x}");
}

TEST(SceneParameters, AnUnsetNameWithoutDefaultIsNamed) {
    EXPECT_EQ(substituted("1 $radius", {}), "missing radius");
    EXPECT_EQ(substituted("${radius}", {{"radiu", "1"}}), "missing radius");
}

TEST(SceneParameters, AssignmentsNeedAName) {
    using Assignment = std::pair<std::string, std::string>;
    EXPECT_EQ(parseParameterAssignment("r=1.5"), Assignment("r", "1.5"));
    EXPECT_EQ(parseParameterAssignment("path=a=b"), Assignment("path", "a=b"));
    EXPECT_EQ(parseParameterAssignment("r="), Assignment("r", ""));
    for (const char* bad : {"r", "=1", "1r=2", "a-b=1", ""})
        EXPECT_THROW(parseParameterAssignment(bad), InputError) << bad;
}

TEST(SceneParameters, FillTheSceneAttributes) {
    const Scene s =
        loadSceneXmlFromString(kSweep, "sweep.xml", ".", {{"red", "0.25"}, {"radius", "2"}, {"unused", "7"}});
    EXPECT_EQ(s.materials[0].color.r, 0.25f);
    EXPECT_EQ(s.camera.fovDegrees, Real(40));
    ASSERT_EQ(s.primitives.size(), 1u);
    EXPECT_EQ(s.primitives.bounds().hi.x, Real(2));
}

TEST(SceneParameters, AnUnsetNameIsAnErrorAtItsLine) {
    EXPECT_EQ(inputErrorOf([] {
                  loadSceneXmlFromString(kSweep, "sweep.xml", ".", {{"red", "1"}});
              }),
              "sweep.xml:5: attribute 'r': parameter $radius has no value (give --set radius=VALUE, or write "
              "${radius:-default})");
}

// The parameters are filled before the loader reads the file, so a hostile file's nesting must
// not cost stack there either: the loader's own limit is the error.
TEST(SceneParameters, DeepNestingIsFilledWithoutRecursion) {
    constexpr int kDepth = 200000;
    std::string xml = R"(<scene><camera><origin /><destination z="1" /></camera><objects>)";
    for (int i = 0; i < kDepth; ++i) xml += R"(<translate x="$x">)";
    for (int i = 0; i < kDepth; ++i) xml += "</translate>";
    xml += "</objects></scene>";
    const std::string error = inputErrorOf([&] { loadSceneXmlFromString(xml, "deep.xml", ".", {{"x", "1"}}); });
    EXPECT_NE(error.find("nested deeper than"), std::string::npos) << error;
}
