#include "io/xml_loader.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <type_traits>

#include "scene_test_files.h"
#include "test_util.h"

using namespace rt;

namespace {

// The example scene printed in thesis 3.4.2, as written, with a 3ds model from the shared
// corpus in place of scenes/spaceship.3ds.
const std::string kThesisExample = R"(<?xml version="1.0" ?>
<scene>
  <background r="0.1" g="0.1" b="0.6" />

  <camera fov="50" zoom="100">
    <origin x="4" y="-4.5" z="-18" />
    <destination x="1" y="-0.5" z="5" />
  </camera>

  <materials>
    <material name="blue" r="0.7" g="0.7" b="1.0"
      diffuse="0.4" reflection="0.4" />
    <material name="red_steel" r="1" g="0" b="0"
      diffuse="0.6" specular="0.3" />
  </materials>

  <models>
    <model name="spaceship" file="SPACESHIP" type="3ds" />
  </models>

  <objects>
    <sphere x="0" y="-1" z="12" r="1.2" material="blue" />
    <scale factor="0.025">
      <rotate ry="1">
        <translate x="-3" z="4.5">
          <model name="spaceship" material="red_steel" />
        </translate>
      </rotate>
    </scale>
  </objects>

  <lights>
    <light x="-1" y="0" z="0" r="0.8" g="0.8" b="0.8" size="0.1" />
  </lights>
</scene>
)";

const std::string kFels = RT_SHARED_DIR "/models/3ds/fels/fels.3ds";

std::string replaced(std::string text, const std::string& what, const std::string& with) {
    text.replace(text.find(what), what.size(), with);
    return text;
}

// A scene with a camera around the given <scene> content.
std::string sceneWith(const std::string& body) {
    return "<scene>\n<camera><origin/><destination z=\"1\"/></camera>\n" + body + "</scene>\n";
}

// With the model reader rt::loadScene gives the loader, which reads 3ds models too.
Scene load(const std::string& body, const std::string& baseDir = ".") {
    return loadSceneXmlFromString(sceneWith(body), "s.xml", baseDir);
}

std::string xmlErrorOf(const std::string& xml) {
    return inputErrorOf([&] { loadSceneXmlFromString(xml, "s.xml", "."); });
}

}  // namespace

TEST(XmlLoader, ThesisExampleLoadsAsWritten) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    const std::string path = dir.write("ships.xml", replaced(kThesisExample, "SPACESHIP", kFels));
    const Scene scene = loadSceneXml(path);

    EXPECT_EQ(scene.background, Color(0.1f, 0.1f, 0.6f));
    ASSERT_TRUE(scene.camera.fovDegrees);
    EXPECT_EQ(*scene.camera.fovDegrees, 50);
    EXPECT_FALSE(scene.camera.focalDistance);
    EXPECT_EQ(scene.camera.zoom, 100);
    EXPECT_EQ(scene.camera.origin, Vec3(4, -4.5, -18));
    EXPECT_EQ(scene.camera.destination, Vec3(1, -0.5, 5));
    EXPECT_EQ(scene.camera.up, Vec3(0, 1, 0));

    ASSERT_EQ(scene.materials.size(), 2u);
    const Material& blue = scene.materials[0];
    EXPECT_EQ(blue.name, "blue");
    EXPECT_EQ(blue.color, Color(0.7f, 0.7f, 1.0f));
    EXPECT_EQ(blue.phong.diffuse, 0.4f);
    EXPECT_EQ(blue.phong.reflection, 0.4f);
    EXPECT_EQ(blue.phong.specular, Material{}.phong.specular);  // not given: the default
    EXPECT_EQ(scene.materials[1].name, "red_steel");
    EXPECT_EQ(scene.materials[1].phong.specular, 0.3f);

    ASSERT_EQ(scene.models.size(), 1u);
    EXPECT_EQ(scene.models[0].name, "spaceship");
    EXPECT_EQ(scene.models[0].format, Model::Format::Max3ds);
    EXPECT_EQ(scene.models[0].triangleCount(), 768u);  // MANIFEST.md: fels.3ds has 768 triangles

    ASSERT_EQ(scene.looseObjects.count<Sphere>(), 1u);
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].center, Vec3(0, -1, 12));
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].radius, Real(1.2));
    EXPECT_EQ(scene.looseObjects.material(0), 0u);

    // "first scaled by 0.025, then rotated about y by pi, and finally translated by -3 on x and 4.5 on z"
    ASSERT_EQ(scene.instances.size(), 1u);
    EXPECT_EQ(scene.instances[0].material, 1u);
    const Transform& xf = scene.instances[0].transform;
    expectNear(xf.point({40, 0, 0}), {-3 - 1, 0, 4.5});
    expectNear(xf.point({0, 40, 80}), {-3, 1, 4.5 - 2});

    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].position, Vec3(-1, 0, 0));
    EXPECT_EQ(scene.lights[0].color, Color(0.8f, 0.8f, 0.8f));
    EXPECT_EQ(scene.lights[0].size, Real(0.1));

    EXPECT_EQ(scene.primitives.count<Sphere>(), 1u);
    EXPECT_EQ(scene.primitives.count<Triangle>() + scene.droppedDegenerate, 768u);
}

TEST(XmlLoader, ModelPathsResolveAgainstTheSceneFolder) {
    TempDir dir;
    std::filesystem::create_directory(dir.path("models"));
    writeRawFile(dir.path("models/tri.raw"), rawModel({0, 0, 0, 1, 0, 0, 0, 1, 0}));
    const std::string path =
        dir.write("scene.xml", sceneWith("<models><model name=\"t\" file=\"models/tri.raw\"/></models>"
                                         "<objects><model name=\"t\"/></objects>"));
    const Scene scene = loadSceneXml(path);
    EXPECT_EQ(scene.models[0].file, "models/tri.raw");
    EXPECT_EQ(scene.models[0].format, Model::Format::Raw);  // from the extension
    EXPECT_EQ(scene.primitives.count<Triangle>(), 1u);
}

TEST(XmlLoader, NestedTransformsApplyOuterFirst) {
    // Outer <translate>, inner <scale>: the point is translated, then scaled.
    const Scene scene = load(R"(<objects><translate x="1"><scale factor="2">
        <sphere x="0" y="0" z="0" r="1"/>
        </scale></translate></objects>)");
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].center, Vec3(2, 0, 0));
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].radius, 2);
    // The other way round, the translation is not scaled.
    const Scene inner = load(R"(<objects><scale factor="2"><translate x="1">
        <sphere x="0" y="0" z="0" r="1"/></translate></scale></objects>)");
    EXPECT_EQ(inner.looseObjects.all<Sphere>()[0].center, Vec3(1, 0, 0));
}

TEST(XmlLoader, RotateAppliesXThenYThenZ) {
    // X first takes +Y to +Z, then Y takes +Z to +X; the other order would give +Z.
    const Scene scene = load(R"(<objects><rotate x="90" y="90"><sphere y="1" r="1"/></rotate></objects>)");
    expectNear(scene.looseObjects.all<Sphere>()[0].center, {1, 0, 0});
    const Scene z = load(R"(<objects><rotate z="90"><sphere x="1" r="1"/></rotate></objects>)");
    expectNear(z.looseObjects.all<Sphere>()[0].center, {0, 1, 0});  // right-handed
}

TEST(XmlLoader, RotateInMultiplesOfPiMatchesDegrees) {
    const Scene scene = load(R"(<objects>
        <rotate rx="0.5" ry="-0.25" rz="1.5"><sphere x="1" y="2" z="3" r="1"/></rotate>
        <rotate x="90" y="-45" z="270"><sphere x="1" y="2" z="3" r="1"/></rotate></objects>)");
    expectNear(scene.looseObjects.all<Sphere>()[0].center, scene.looseObjects.all<Sphere>()[1].center);
}

TEST(XmlLoader, ScaleByFactorOrPerAxis) {
    const Scene scene = load(R"(<objects>
        <scale x="2" y="3"><sphere x="1" y="1" z="1" r="1"/></scale>
        <scale factor="-0.5"><sphere x="1" y="1" z="1" r="1"/></scale></objects>)");
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].center, Vec3(2, 3, 1));
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].radius, 3);  // the largest stretch
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[1].center, Vec3(-0.5, -0.5, -0.5));
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[1].radius, 0.5);
}

TEST(XmlLoader, TranslateAndTheThesisAliasTransform) {
    const Scene scene = load(R"(<objects><translate x="1" y="2" z="3"><transform y="-2">
        <sphere r="1"/></transform></translate></objects>)");
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].center, Vec3(1, 0, 3));
}

TEST(XmlLoader, NumbersTooSmallForRealRoundToZero) {
    const Scene scene = load(R"(<objects><sphere x="1e-400" y="-1e-500" r="+2.5e0"/></objects>)");
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].center, Vec3(0, 0, 0));
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].radius, 2.5);
}

TEST(XmlLoader, MatrixIsRowMajorThreeByFour) {
    const Scene scene = load(R"(<objects><matrix m="0 -1 0 10  1 0 0 20  0 0 2 30">
        <sphere x="1" y="2" z="3" r="1"/></matrix></objects>)");
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].center, Vec3(10 - 2, 20 + 1, 30 + 6));
    EXPECT_EQ(scene.looseObjects.all<Sphere>()[0].radius, 2);
}

TEST(XmlLoader, TrianglesAndQuads) {
    const Scene scene = load(R"(<materials><material name="m"/></materials><objects>
        <triangle material="m"><vertex x="0" y="0" z="0"/><vertex x="1"/><vertex y="1"/></triangle>
        <quad><vertex/><vertex x="2"/><vertex x="2" y="2"/><vertex y="2"/></quad></objects>)");
    ASSERT_EQ(scene.looseObjects.count<Triangle>(), 3u);
    EXPECT_EQ(scene.looseObjects.all<Triangle>()[0].p1, Vec3(1, 0, 0));
    EXPECT_EQ(scene.looseObjects.all<Triangle>()[0].p2, Vec3(0, 1, 0));
    // The quad is split along the diagonal from its first to its third corner.
    EXPECT_EQ(scene.looseObjects.all<Triangle>()[1].p2, Vec3(2, 2, 0));
    EXPECT_EQ(scene.looseObjects.all<Triangle>()[2].p1, Vec3(2, 2, 0));
    EXPECT_EQ(scene.looseObjects.all<Triangle>()[2].p2, Vec3(0, 2, 0));
    EXPECT_NEAR(scene.looseObjects.all<Triangle>()[1].area() + scene.looseObjects.all<Triangle>()[2].area(), 4, kTol);
    EXPECT_EQ(scene.looseObjects.material(0), 0u);
    EXPECT_EQ(scene.materials[scene.looseObjects.material(1)].name, "default");
}

TEST(XmlLoader, ObjectsWithoutMaterialUseTheDefault) {
    const Scene added = load(R"(<objects><sphere r="1"/><sphere r="2"/></objects>)");
    ASSERT_EQ(added.materials.size(), 1u);  // added once, with the Material defaults
    EXPECT_EQ(added.materials[0].name, "default");
    EXPECT_EQ(added.materials[0].phong.diffuse, Material{}.phong.diffuse);
    const Scene own = load(R"(<materials><material name="x"/><material name="default" r="0.5"/></materials>
        <objects><sphere r="1"/></objects>)");
    ASSERT_EQ(own.materials.size(), 2u);  // the scene's own "default" is used
    EXPECT_EQ(own.looseObjects.material(0), 1u);
    EXPECT_EQ(load("").materials.size(), 0u);  // nothing added when nothing needs it
}

TEST(XmlLoader, EveryMaterialAttribute) {
    const Scene scene = load(R"(<materials><material name="all" r="0.25" g="0.5" b="2" ambient="0.2"
        diffuse="0.3" specular="0.4" shininess="50" reflection="0.6" spread="0.05"/></materials>)");
    const Material& m = scene.materials.at(0);
    EXPECT_EQ(m.color, Color(0.25f, 0.5f, 2));
    EXPECT_EQ(m.phong.ambient, 0.2f);
    EXPECT_EQ(m.phong.diffuse, 0.3f);
    EXPECT_EQ(m.phong.specular, 0.4f);
    EXPECT_EQ(m.phong.shininess, 50);
    EXPECT_EQ(m.phong.reflection, 0.6f);
    EXPECT_EQ(m.phong.spread, 0.05f);
    const Material defaults = load(R"(<materials><material name="d"/></materials>)").materials.at(0);
    EXPECT_EQ(defaults.color, Color(1, 1, 1));
    EXPECT_EQ(defaults.phong.ambient, Material{}.phong.ambient);
    EXPECT_EQ(defaults.phong.shininess, Material{}.phong.shininess);
}

TEST(XmlLoader, CameraFocalDistanceZoomAndUp) {
    const Scene f = loadSceneXmlFromString(R"(<scene><camera f="800" zoom="50"><origin x="1"/>
        <destination x="1" z="-3"/><up z="1" x="1"/></camera></scene>)",
                                           "s.xml", ".");
    EXPECT_EQ(*f.camera.focalDistance, 800);
    EXPECT_FALSE(f.camera.fovDegrees);
    EXPECT_EQ(f.camera.up, Vec3(1, 0, 1));
    EXPECT_EQ(f.camera.focalPixels(kReferenceWidth), 400);  // f is in pixels of an 800-pixel-wide picture
    // Neither fov nor f: the distance from origin to destination (thesis 3.4.2).
    const Scene d = loadSceneXmlFromString(R"(<scene><camera><origin x="1"/><destination x="1" z="-3"/>
        </camera></scene>)",
                                           "s.xml", ".");
    EXPECT_EQ(d.camera.focalPixels(kReferenceWidth), 3);
    EXPECT_EQ(d.camera.zoom, 100);
    // fov is the horizontal angle: f = w / (2 tan(fov/2)).
    const Scene fov = loadSceneXmlFromString(R"(<scene><camera fov="90"><origin/><destination z="1"/>
        </camera></scene>)",
                                             "s.xml", ".");
    EXPECT_NEAR(fov.camera.focalPixels(640), 320, 1e-3);
}

TEST(XmlLoader, SeveralNamedCamerasTheFirstRendered) {
    const Scene s = loadSceneXmlFromString(R"(<scene><camera name="front"><origin/><destination z="1"/></camera>
        <camera name="side" fov="30"><origin x="5"/><destination/></camera>
        <camera><origin y="5"/><destination/><up z="1"/></camera></scene>)",
                                           "s.xml", ".");
    EXPECT_EQ(s.camera.name, "front");
    ASSERT_EQ(s.extraCameras.size(), 2u);
    EXPECT_EQ(s.extraCameras[0].name, "side");
    EXPECT_EQ(s.extraCameras[0].fovDegrees, Real(30));
    EXPECT_EQ(s.extraCameras[1].name, "");
    EXPECT_EQ(s.extraCameras[1].origin, Vec3(0, 5, 0));
}

TEST(XmlLoader, BackgroundAndLights) {
    const Scene scene = load(R"(<background g="0.5"/><lights><light x="1" y="2" z="3"/>
        <light r="0.5" g="0.25" b="0" size="2"/></lights>)");
    EXPECT_EQ(scene.background, Color(0, 0.5f, 0));
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].position, Vec3(1, 2, 3));
    EXPECT_EQ(scene.lights[0].color, Color(1, 1, 1));
    EXPECT_EQ(scene.lights[0].size, 0);
    EXPECT_EQ(scene.lights[1].color, Color(0.5f, 0.25f, 0));
    EXPECT_EQ(scene.lights[1].size, 2);
    EXPECT_EQ(load("").background, Color(0, 0, 0));  // thesis: black when not given
}

// rt extension: directional and spot lights, the inverse-square falloff and its range.
TEST(XmlLoader, LightTypesFalloffAndCone) {
    const Scene scene = load(R"(<lights><light type="directional" dx="0" dy="-2" dz="0" r="0.5"/>
        <light type="spot" x="1" dy="-1" dz="0" falloff="inverse_square" range="7" inner_cone="5" outer_cone="20"/>
        <light type="spot" falloff="inverse_square"/><light/></lights>)");
    ASSERT_EQ(scene.lights.size(), 4u);
    const Light &sun = scene.lights[0], &spot = scene.lights[1], &plain = scene.lights[2], &thesis = scene.lights[3];
    EXPECT_EQ(sun.type, Light::Type::Directional);
    EXPECT_EQ(sun.direction, Vec3(0, -1, 0));
    EXPECT_EQ(sun.falloff, Light::Falloff::None);
    EXPECT_EQ(spot.type, Light::Type::Spot);
    EXPECT_EQ(spot.position, Vec3(1, 0, 0));
    EXPECT_EQ(spot.falloff, Light::Falloff::InverseSquare);
    EXPECT_EQ(spot.range, 7);
    EXPECT_EQ(spot.innerConeDegrees, 5);
    EXPECT_EQ(spot.outerConeDegrees, 20);
    EXPECT_EQ(plain.direction, Vec3(0, 0, -1));  // KHR_lights_punctual's defaults: -Z, cone 0 to 45 degrees
    EXPECT_EQ(plain.innerConeDegrees, 0);
    EXPECT_EQ(plain.outerConeDegrees, 45);
    EXPECT_EQ(plain.range, 0);
    EXPECT_EQ(thesis.type, Light::Type::Point);  // the thesis's light: no falloff
    EXPECT_EQ(thesis.falloff, Light::Falloff::None);
}

TEST(XmlLoader, ModelInstancesShareOneModel) {
    TempDir dir;
    writeRawFile(dir.path("tri.raw"), rawModel({0, 0, 0, 1, 0, 0, 0, 1, 0}));
    const Scene scene = load(R"(<models><model name="t" file="tri.raw" type="raw"/></models>
        <materials><material name="m"/></materials>
        <objects><model name="t"/><translate x="5"><model name="t" material="m"/></translate></objects>)",
                             dir.path(""));
    ASSERT_EQ(scene.models.size(), 1u);
    ASSERT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.instances[0].material, 1u);  // "default", added after "m"
    EXPECT_EQ(scene.instances[1].material, 0u);
    ASSERT_EQ(scene.primitives.count<Triangle>(), 2u);
    EXPECT_EQ(scene.primitives.all<Triangle>()[1].p1, Vec3(6, 0, 0));
}

TEST(XmlLoader, InlineBase64Model) {
    // "raw3d" 'S', count 1, then the sphere (1, 2, 3) radius 0.5 as little-endian floats.
    const Scene scene = load(R"(<models><model name="s" type="raw" encoding="base64">
        cmF3M2RTAQAAAAAAgD8AAABA
        AABAQAAAAD8=
        </model></models><objects><model name="s"/></objects>)");
    ASSERT_EQ(scene.primitives.count<Sphere>(), 1u);
    EXPECT_EQ(scene.primitives.all<Sphere>()[0].center, Vec3(1, 2, 3));
    EXPECT_EQ(scene.primitives.all<Sphere>()[0].radius, 0.5);
    EXPECT_EQ(scene.models[0].file, "");
}

TEST(XmlLoader, DegeneratePrimitivesAreDroppedAndCounted) {
    // RAW model: one good triangle and one with all three corners on a line.
    const Scene scene = load(R"(<models><model name="s" encoding="base64">
        cmF3M2RUAgAAAAAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAEAAAAAAAAAAAA==
        </model></models><objects>
        <model name="s"/>
        <sphere r="0"/><sphere r="-1"/><sphere r="1"/>
        <triangle><vertex/><vertex x="1"/><vertex x="2"/></triangle></objects>)");
    EXPECT_EQ(scene.looseObjects.count<Sphere>(), 1u);
    EXPECT_EQ(scene.primitives.size(), 2u);
    EXPECT_EQ(scene.droppedDegenerate, 4u);
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0], "dropped 4 degenerate primitives (zero-area triangles, spheres with radius <= 0)");
    EXPECT_TRUE(load("").warnings.empty());
}

TEST(XmlLoader, ThreeDsModelsBakeNodeTransforms) {
    SKIP_WITHOUT_SHARED_MODELS();
    const Scene scene =
        load("<models><model name=\"j\" file=\"" RT_SHARED_DIR "/models/3ds/jeep1/jeep1.3ds\"/></models>");
    EXPECT_EQ(scene.models.at(0).format, Model::Format::Max3ds);  // from the extension
    EXPECT_EQ(scene.models.at(0).triangleCount(), 2032u);         // MANIFEST.md
}

// The loader reads a 3ds model itself (io/model_file.h): a file that is not 3DS reaches the 3ds
// reader's own check, with the scene's line in front.
TEST(XmlLoader, ThreeDsModelsAreReadByTheLoaderItself) {
    TempDir dir;
    dir.write("ship.3ds", "not a 3ds file");
    const std::string xml = sceneWith("<models>\n<model name=\"m\" file=\"ship.3ds\"/></models>");
    EXPECT_EQ(inputErrorOf([&] { loadSceneXmlFromString(xml, "s.xml", dir.path(".")); }),
              "s.xml:4: model 'm': " + dir.path("./ship.3ds") +
                  ": cannot read 3ds model: not a 3DS file (no 0x4D4D main chunk at byte 0)");
}

namespace {

struct BadScene {
    const char* what;
    std::string xml;
    std::string error;  // the whole message
};

std::string repeated(const std::string& text, int times) {
    std::string all;
    for (int i = 0; i < times; ++i) all += text;
    return all;
}

constexpr bool kFloatGeometry = std::is_same_v<Real, float>;

// Line 1 <scene>, line 2 the camera, the case's content from line 3.
const BadScene kBadScenes[] = {
    {"malformed XML", sceneWith("<objects>\n<sphere r=\"1\">\n</objects>\n"),
     "s.xml:5: malformed XML: Start-end tags mismatch"},
    {"unknown attribute", sceneWith("<materials>\n<material name=\"m\" colour=\"1\"/></materials>"),
     "s.xml:4: unknown attribute 'colour' on <material>"},
    {"unknown element", sceneWith("\n<object/>"), "s.xml:4: unknown element <object> in <scene>"},
    {"unknown object", sceneWith("<objects>\n<rotate>\n<cube/></rotate></objects>"),
     "s.xml:5: unknown element <cube> in <rotate>"},
    {"text", sceneWith("<objects>\nhello<sphere r=\"1\"/></objects>"), "s.xml:4: unexpected text in <objects>"},
    {"missing attribute", sceneWith("<objects>\n\n<sphere x=\"1\"/></objects>"),
     "s.xml:5: <sphere> needs attribute 'r'"},
    {"disk without a normal", sceneWith("<objects>\n<disk r=\"1\" nx=\"1\" ny=\"0\"/></objects>"),
     "s.xml:4: <disk> needs attribute 'nz'"},
    {"unknown attribute of a disk",
     sceneWith("<objects>\n<disk r=\"1\" nx=\"1\" ny=\"0\" nz=\"0\" h=\"1\"/></objects>"),
     "s.xml:4: unknown attribute 'h' on <disk>"},
    {"not a number", sceneWith("<objects><sphere\n r=\"1cm\"/></objects>"),
     "s.xml:3: <sphere> attribute 'r': '1cm' is not a number"},
    {"empty number", sceneWith("<background r=\"\"/>"), "s.xml:3: <background> attribute 'r': '' is not a number"},
    {"NaN", sceneWith("<lights>\n<light x=\"nan\"/></lights>"),
     "s.xml:4: <light> attribute 'x': 'nan' is not a finite number"},
    {"infinity", sceneWith("<objects>\n<translate y=\"-inf\"/></objects>"),
     "s.xml:4: <translate> attribute 'y': '-inf' is not a finite number"},
    {"overflow", sceneWith("<objects>\n<translate y=\"1e999\"/></objects>"),
     "s.xml:4: <translate> attribute 'y': '1e999' is not a finite number"},
    {"missing material", sceneWith("<objects>\n<sphere r=\"1\" material=\"gold\"/></objects>"),
     "s.xml:4: unknown material 'gold'"},
    {"duplicate material", sceneWith("<materials>\n<material name=\"m\"/>\n<material name=\"m\"/></materials>"),
     "s.xml:5: duplicate material 'm' (first defined on line 4)"},
    {"missing model", sceneWith("<objects>\n<model name=\"ship\"/></objects>"), "s.xml:4: unknown model 'ship'"},
    {"duplicate model",
     sceneWith("<models><model name=\"s\" encoding=\"base64\">cmF3M2RUAAAAAA==</model>\n"
               "<model name=\"s\" encoding=\"base64\">cmF3M2RUAAAAAA==</model></models>"),
     "s.xml:4: duplicate model 's' (first defined on line 3)"},
    {"missing model file", sceneWith("<models>\n<model name=\"s\" file=\"no/such.raw\"/></models>"),
     "s.xml:4: model 's': ./no/such.raw: cannot open: No such file or directory"},
    {"bad inline RAW", sceneWith("<models>\n<model name=\"s\" encoding=\"base64\">cmF3M2RUAQAAAA==</model></models>"),
     "s.xml:4: model 's': inline RAW data: byte 10: truncated RAW data: 36 bytes of data for 1 triangle, "
     "the file has 0"},
    {"bad base64", sceneWith("<models>\n<model name=\"s\" encoding=\"base64\">cmF3M2R*</model></models>"),
     "s.xml:4: model 's': bad base64 at character 7"},
    {"unknown model type", sceneWith("<models>\n<model name=\"s\" file=\"x.obj\"/></models>"),
     "s.xml:4: <model> needs type=\"raw\" or type=\"3ds\" (the file name does not tell)"},
    {"no camera", "<scene>\n</scene>", "s.xml:1: <scene> needs a <camera>"},
    {"two cameras of one name",
     sceneWith("<camera name=\"a\"><origin/><destination z=\"1\"/></camera>\n<camera name=\"a\"/>"),
     "s.xml:4: duplicate camera 'a' (first defined on line 3)"},
    {"camera without destination", "<scene><camera>\n<origin/></camera></scene>",
     "s.xml:1: <camera> needs <origin> and <destination>"},
    {"camera looking nowhere", "<scene><camera><origin/><destination/></camera></scene>",
     "s.xml:1: camera origin and destination coincide"},
    {"camera up along the view", "<scene><camera><origin/><destination z=\"1\"/><up z=\"2\"/></camera></scene>",
     "s.xml:1: camera up vector is zero or parallel to the view direction"},
    {"second up", "<scene><camera><origin/><destination z=\"1\"/><up/>\n<up/></camera></scene>",
     "s.xml:2: a second <up> in <camera>"},
    {"fov and f", "<scene><camera fov=\"40\" f=\"2\"><origin/><destination z=\"1\"/></camera></scene>",
     "s.xml:1: <camera> takes fov or f, not both"},
    {"fov out of range", "<scene><camera fov=\"180\"><origin/><destination z=\"1\"/></camera></scene>",
     "s.xml:1: <camera> fov must be between 0 and 180 degrees"},
    {"triangle with two vertices", sceneWith("<objects>\n<triangle><vertex/><vertex/></triangle></objects>"),
     "s.xml:4: <triangle> needs 3 <vertex> elements, not 2"},
    {"zero scale", sceneWith("<objects>\n<scale y=\"0\"/></objects>"), "s.xml:4: <scale> factors must not be zero"},
    {"singular matrix", sceneWith("<objects>\n<matrix m=\"1 0 0 0 0 1 0 0 0 0 0 0\"/></objects>"),
     "s.xml:4: <matrix> is singular"},
    {"short matrix", sceneWith("<objects>\n<matrix m=\"1 0 0 0 0 1 0 0 0 0 1\"/></objects>"),
     "s.xml:4: <matrix> attribute 'm' needs exactly 12 numbers"},
    {"both rotation forms", sceneWith("<objects>\n<rotate y=\"90\" ry=\"0.5\"/></objects>"),
     "s.xml:4: <rotate> takes y or ry, not both"},
    {"negative colour", sceneWith("<lights>\n<light g=\"-1\"/></lights>"),
     "s.xml:4: <light> attribute 'g' must not be negative"},
    // Beyond float: too large for the colour in the double build, for any number in the float build.
    {"colour beyond float", sceneWith("<lights>\n<light r=\"1e308\"/></lights>"),
     kFloatGeometry ? "s.xml:4: <light> attribute 'r': '1e308' is not a finite number"
                    : "s.xml:4: <light> attribute 'r' is too large (at most 1e15)"},
    {"material factor beyond float", sceneWith("<materials>\n<material name=\"m\" diffuse=\"1e39\"/></materials>"),
     kFloatGeometry ? "s.xml:4: <material> attribute 'diffuse': '1e39' is not a finite number"
                    : "s.xml:4: <material> attribute 'diffuse' is too large (at most 1e15)"},
    // Within float but beyond what a scene may hold (docs/robustness.md, Limits).
    {"light beyond 1e15", sceneWith("<lights>\n<light r=\"3.4e38\"/></lights>"),
     "s.xml:4: <light> attribute 'r' is too large (at most 1e15)"},
    {"texture scale beyond 1e6",
     sceneWith("<textures>\n<texture name=\"t\" type=\"checker\" scale=\"1 2e6\"/></textures>"),
     "s.xml:4: <texture> attribute 'scale' is out of range (at most 1e6 in magnitude)"},
    {"texture rotation beyond 1e6",
     sceneWith("<textures>\n<texture name=\"t\" type=\"checker\" rotation=\"-2e6\"/></textures>"),
     "s.xml:4: <texture> attribute 'rotation' is out of range (-1e+06 to 1e+06)"},
    {"ior beyond 100", sceneWith("<materials>\n<material name=\"m\" transmission=\"1\" ior=\"1e30\"/></materials>"),
     "s.xml:4: <material> ior must be at most 100"},
    {"sphere beyond 1e15", sceneWith("<objects>\n<sphere x=\"1e16\" r=\"1\"/></objects>"),
     "s.xml:4: <sphere> reaches beyond 1e15 from the origin, where no ray can find it"},
    {"transforms nested too deep",
     sceneWith("<objects>\n" + repeated("<translate>", 300) + repeated("</translate>", 300) + "</objects>"),
     "s.xml:4: transforms nested deeper than 256"},
    {"DOCTYPE naming a file", "<!DOCTYPE scene [ <!ENTITY x SYSTEM \"/etc/passwd\"> ]>\n<scene>&x;</scene>",
     "s.xml:1: DOCTYPE is not allowed: scenes have no DTD and no entities"},
    {"unknown light type", sceneWith("<lights>\n<light type=\"area\"/></lights>"),
     "s.xml:4: unknown type 'area' (point, directional, spot)"},
    {"directional light with a position", sceneWith("<lights>\n<light type=\"directional\" y=\"1\"/></lights>"),
     "s.xml:4: a directional light has no 'y'"},
    {"range without falloff", sceneWith("<lights>\n<light range=\"3\"/></lights>"),
     "s.xml:4: 'range' needs falloff=\"inverse_square\""},
    {"unknown falloff", sceneWith("<lights>\n<light falloff=\"linear\"/></lights>"),
     "s.xml:4: unknown falloff 'linear' (none, inverse_square)"},
    {"point light with a direction", sceneWith("<lights>\n<light dz=\"1\"/></lights>"),
     "s.xml:4: a point light has no direction ('dz')"},
    {"cone of a point light", sceneWith("<lights>\n<light outer_cone=\"10\"/></lights>"),
     "s.xml:4: 'outer_cone' is for spot lights"},
    {"zero direction", sceneWith("<lights>\n<light type=\"spot\" dz=\"0\"/></lights>"),
     "s.xml:4: the light's direction (dx, dy, dz) is zero"},
    {"inner cone wider than outer", sceneWith("<lights>\n<light type=\"spot\" inner_cone=\"50\"/></lights>"),
     "s.xml:4: a spot needs 0 <= inner_cone <= outer_cone <= 90 (degrees)"},
    {"headlight with a position", sceneWith("<lights>\n<light headlight=\"true\" x=\"1\"/></lights>"),
     "s.xml:4: a headlight sits at the camera: it has no 'x'"},
    {"headlight that is a spot", sceneWith("<lights>\n<light type=\"spot\" headlight=\"true\"/></lights>"),
     "s.xml:4: a headlight is a point light"},
    {"wrong root", "<?xml version=\"1.0\"?>\n<scenery/>", "s.xml:2: the root element must be <scene>"},
    {"empty file", "", "s.xml:1: malformed XML: No document element found"},
};

void PrintTo(const BadScene& bad, std::ostream* os) { *os << bad.what; }

class XmlLoaderBadInput : public ::testing::TestWithParam<BadScene> {};

}  // namespace

TEST_P(XmlLoaderBadInput, GivesOneErrorWithFileAndLine) {
    EXPECT_EQ(xmlErrorOf(GetParam().xml), GetParam().error) << GetParam().what;
}

INSTANTIATE_TEST_SUITE_P(Cases, XmlLoaderBadInput, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadScene>& param) {
                             std::string name = param.param.what;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

// Scale factors computed from Real's range, so that the double and the float build both see a
// finite factor whose transform is not: its determinant (the cube) overflows or its inverse does.
TEST(XmlLoader, TransformsWithoutAFiniteInverseAreInputErrors) {
    const auto scale = [](Real factor) {
        std::ostringstream s;
        s << std::setprecision(std::numeric_limits<Real>::max_digits10) << "<scale factor=\"" << factor << "\">";
        return s.str();
    };
    const Real huge = std::cbrt(std::numeric_limits<Real>::max()) * 2;
    const Real tiny = std::cbrt(std::numeric_limits<Real>::min()) / 2;
    const Real root = std::sqrt(huge);  // fine alone, not twice
    const std::string error = "s.xml:4: <scale> makes the transform singular or not finite";
    EXPECT_EQ(xmlErrorOf(sceneWith("<objects>\n" + scale(huge) + "</scale></objects>")), error);
    EXPECT_EQ(xmlErrorOf(sceneWith("<objects>\n" + scale(tiny) + "</scale></objects>")), error);
    EXPECT_EQ(xmlErrorOf(sceneWith("<objects>" + scale(root) + "\n" + scale(root) + "</scale></scale></objects>")),
              error);
}

TEST(XmlLoader, BadModelFilesGiveTheSceneLine) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    dir.write("short.raw", std::string("raw3dS\x02\0\0\0", 10) + std::string(20, '\0'));
    const std::string path = dir.write("s.xml", sceneWith("<models>\n<model name=\"m\" file=\"short.raw\"/></models>"));
    EXPECT_EQ(inputErrorOf([&] { loadSceneXml(path); }),
              path + ":4: model 'm': " + dir.path("short.raw") +
                  ": byte 30: truncated RAW data: 32 bytes of data for 2 spheres, the file has 20");
    for (const char* bad : {"derived-3ds/fels_truncated_4096.3ds", "derived-3ds/test1_bad_main_chunk_length.3ds",
                            "derived-3ds/random_bytes_named.3ds", "assimp-invalid/empty.3ds"}) {
        const std::string model = std::string(RT_SHARED_DIR "/models/bad/") + bad;
        const std::string error =
            xmlErrorOf(sceneWith("<models><model name=\"m\" type=\"3ds\" file=\"" + model + "\"/></models>"));
        EXPECT_EQ(error.rfind("s.xml:3: model 'm': " + model + ": cannot read 3ds model: ", 0), 0u) << error;
    }
}

TEST(XmlLoader, DashReadsStandardInput) {
    std::istringstream in(sceneWith("<objects>\n<sphere r=\"1\"/>\n<sphere r=\"x\"/></objects>"));
    std::streambuf* old = std::cin.rdbuf(in.rdbuf());
    const std::string error = inputErrorOf([] { loadSceneXml("-"); });
    std::cin.rdbuf(old);
    EXPECT_EQ(error, "<stdin>:5: <sphere> attribute 'r': 'x' is not a number");
}

TEST(XmlLoader, MissingSceneFile) {
    EXPECT_EQ(inputErrorOf([] { loadSceneXml("/nonexistent/scene.xml"); }),
              "/nonexistent/scene.xml: cannot open: No such file or directory");
}

TEST(XmlLoader, CylindersAndConesUnderTransforms) {
    const Scene scene = load(R"(<objects>
        <scale factor="2"><translate x="1">
          <cylinder x0="0" y0="0" z0="0" x1="0" y1="1" z1="0" r="0.5"/>
          <cone x0="0" y0="0" z0="0" r0="1" x1="0" y1="0" z1="3" r1="0"/>
        </translate></scale>
        <cone x0="0" y0="0" z0="0" r0="0" x1="0" y1="0" z1="1" r1="0"/></objects>)");
    ASSERT_EQ(scene.looseObjects.count<Cylinder>(), 1u);
    ASSERT_EQ(scene.looseObjects.count<Cone>(), 1u);  // the one without a radius is dropped
    EXPECT_EQ(scene.droppedDegenerate, 1u);
    const Cylinder& c = scene.looseObjects.all<Cylinder>()[0];
    expectNear(c.base, {1, 0, 0});  // the outer <scale> applies first
    expectNear(c.top, {1, 2, 0});
    EXPECT_NEAR(c.baseRadius, 1, kTol);
    EXPECT_NEAR(c.topRadius, 1, kTol);
    const Cone& k = scene.looseObjects.all<Cone>()[0];
    expectNear(k.top, {1, 0, 6});
    EXPECT_NEAR(k.baseRadius, 2, kTol);
    EXPECT_EQ(k.topRadius, 0);
}

TEST(XmlLoader, DisksUnderTransforms) {
    const Scene scene = load(R"(<objects>
        <scale x="1" y="1" z="2"><translate x="1">
          <disk x="0" y="0" z="1" nx="1" ny="0" nz="1" r="0.5"/>
        </translate></scale>
        <disk x="0" y="0" z="0" nx="0" ny="3" nz="0" r="1"/>
        <disk x="0" y="0" z="0" nx="0" ny="0" nz="0" r="1"/>
        <disk x="0" y="0" z="0" nx="0" ny="0" nz="1" r="0"/></objects>)");
    ASSERT_EQ(scene.looseObjects.count<Disk>(), 2u);  // those without a normal or a radius are dropped
    EXPECT_EQ(scene.droppedDegenerate, 2u);
    const Disk& placed = scene.looseObjects.all<Disk>()[0];
    expectNear(placed.center, {1, 0, 2});
    // A normal goes through the inverse transpose: the plane x + z = 1 becomes x + z / 2 = 2.
    expectNear(placed.planeNormal, normalize(Vec3{1, 0, Real(0.5)}));
    EXPECT_NEAR(placed.radius, 1, kTol);  // the largest stretch, as a sphere's
    EXPECT_EQ(scene.looseObjects.all<Disk>()[1].planeNormal, Vec3(0, 1, 0));
}
