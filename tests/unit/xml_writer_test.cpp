#include "io/xml_writer.h"

#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <tuple>

#include "io/xml_loader.h"
#include "os/input_file.h"
#include "scene_test_files.h"
#include "test_util.h"

using namespace rt;

namespace {

// Numbers chosen to catch lossy printing: thirds, tiny and huge values, a negative zero.
const std::string kScene = R"(<scene>
  <background r="0.1" g="0.2" b="0.30000001"/>
  <camera fov="47.123456789" zoom="150"><origin x="0.1" y="-4.5" z="-18"/><destination x="1" y="-0.5" z="5"/>
    <up x="0.2" y="1"/></camera>
  <materials>
    <material name="blue" r="0.7" g="0.7" b="1" diffuse="0.4" reflection="0.4" spread="0.01"/>
    <material name="red steel &amp; more" r="1" g="0" b="0" diffuse="0.6" specular="0.3" shininess="77.7"/>
  </materials>
  <models>
    <model name="ship/one" file="FELS" type="3ds"/>
    <model name="balls" encoding="base64">cmF3M2RTAQAAAAAAgD8AAABAAABAQAAAAD8=</model>
  </models>
  <objects>
    <sphere x="0.333333333333333314829616256247" y="-0" z="1e-300" r="1.2" material="blue"/>
    <rotate x="33.3" y="-71" z="12.5"><scale x="0.025" y="0.03" z="-0.02"><translate x="-3" z="4.5">
      <model name="ship/one" material="red steel &amp; more"/>
      <triangle><vertex x="0.1" y="0.2" z="0.3"/><vertex x="1e10"/><vertex y="-7.77"/></triangle>
      <quad material="blue"><vertex/><vertex x="1"/><vertex x="1" y="1"/><vertex y="1"/></quad>
      <cylinder x0="0.1" y0="-2" z0="3" x1="1" y1="1" z1="1" r="0.3" material="blue"/>
      <cone x0="1" y0="0" z0="0" r0="0.7" x1="0" y1="0.1" z1="0" r1="0"/>
      <disk x="0.5" y="1" z="-2" nx="0.3" ny="1" nz="0" r="0.4" material="blue"/>
    </translate></scale></rotate>
    <disk x="1" y="2" z="3" nx="0" ny="0" nz="1" r="2"/>
    <model name="balls"/>
    <translate x="5"><model name="balls" material="blue"/></translate>
  </objects>
  <lights><light x="-1" y="0.1" z="1e-3" r="0.8" g="0.7" b="0.6" size="0.1"/><light/>
    <light type="spot" x="1" y="2" z="3" dx="0.1" dy="-1" falloff="inverse_square" range="10" inner_cone="10"
      outer_cone="30.5" size="0.2"/>
    <light type="directional" dx="1" dy="-1" r="0.5"/><light falloff="inverse_square" r="3"/></lights>
</scene>
)";

Scene loadTestScene(const TempDir& dir) {
    std::string xml = kScene;
    xml.replace(xml.find("FELS"), 4, RT_SHARED_DIR "/models/3ds/fels/fels.3ds");
    return loadSceneXml(dir.write("in/scene.xml", xml));  // the 3ds model too
}

void expectSamePrimitives(const Primitives& a, const Primitives& b) {
    forEachKind([&]<class K>(std::type_identity<K>) { EXPECT_TRUE(sameBits(a.all<K>(), b.all<K>())) << K::kName; });
    ASSERT_EQ(a.size(), b.size());
    for (std::uint32_t id = 0; id < a.size(); ++id) EXPECT_EQ(a.material(id), b.material(id)) << id;
}

// A material's Phong terms, compared at once (a failure prints all six).
auto phongTermsOf(const Material& m) {
    const PhongTerms& p = m.phong;
    return std::tuple{p.ambient, p.diffuse, p.specular, p.shininess, p.reflection, p.spread};
}

void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.background, b.background);
    EXPECT_EQ(a.camera.origin, b.camera.origin);
    EXPECT_EQ(a.camera.destination, b.camera.destination);
    EXPECT_EQ(a.camera.up, b.camera.up);
    EXPECT_EQ(a.camera.fovDegrees, b.camera.fovDegrees);
    EXPECT_EQ(a.camera.focalDistance, b.camera.focalDistance);
    EXPECT_EQ(a.camera.zoom, b.camera.zoom);
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        const Material &x = a.materials[i], &y = b.materials[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_EQ(x.color, y.color);
        EXPECT_EQ(phongTermsOf(x), phongTermsOf(y));
    }
    ASSERT_EQ(a.models.size(), b.models.size());
    for (std::size_t i = 0; i < a.models.size(); ++i) {
        EXPECT_EQ(a.models[i].name, b.models[i].name);
        EXPECT_TRUE(sameBits(a.models[i].triangleVertices, b.models[i].triangleVertices));
        EXPECT_TRUE(sameBits(a.models[i].sphereData, b.models[i].sphereData));
    }
    ASSERT_EQ(a.instances.size(), b.instances.size());
    for (std::size_t i = 0; i < a.instances.size(); ++i) {
        EXPECT_EQ(a.instances[i].model, b.instances[i].model);
        EXPECT_EQ(a.instances[i].material, b.instances[i].material);
        EXPECT_TRUE(a.instances[i].transform == b.instances[i].transform);
    }
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (std::size_t i = 0; i < a.lights.size(); ++i) {
        EXPECT_EQ(a.lights[i].position, b.lights[i].position);
        EXPECT_EQ(a.lights[i].color, b.lights[i].color);
        EXPECT_EQ(a.lights[i].size, b.lights[i].size);
        EXPECT_EQ(a.lights[i].type, b.lights[i].type);
        EXPECT_LT(length(a.lights[i].direction - b.lights[i].direction), 1e-6);  // unit, renormalised
        EXPECT_EQ(a.lights[i].falloff, b.lights[i].falloff);
        EXPECT_EQ(a.lights[i].range, b.lights[i].range);
        EXPECT_EQ(a.lights[i].innerConeDegrees, b.lights[i].innerConeDegrees);
        EXPECT_EQ(a.lights[i].outerConeDegrees, b.lights[i].outerConeDegrees);
    }
    expectSamePrimitives(a.looseObjects, b.looseObjects);
    expectSamePrimitives(a.primitives, b.primitives);
}

// What saveSceneXml(scene, "-") writes to standard output.
std::string savedToStdout(const Scene& scene) {
    std::ostringstream captured;
    std::streambuf* old = std::cout.rdbuf(captured.rdbuf());
    try {
        saveSceneXml(scene, "-");
    } catch (...) {
        std::cout.rdbuf(old);
        throw;
    }
    std::cout.rdbuf(old);
    return captured.str();
}

}  // namespace

TEST(XmlWriter, LoadSaveLoadGivesTheSameScene) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    const Scene first = loadTestScene(dir);
    ASSERT_EQ(first.instances.size(), 3u);
    ASSERT_TRUE(std::signbit(first.looseObjects.all<Sphere>()[0].center.y));

    saveSceneXml(first, dir.path("out/scene.xml"));
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.path("out/scene/ship_one.raw")));
    EXPECT_TRUE(std::filesystem::is_regular_file(dir.path("out/scene/balls.raw")));
    const Scene second = loadSceneXml(dir.path("out/scene.xml"));
    expectSameScene(first, second);
    EXPECT_EQ(second.models[0].file, "scene/ship_one.raw");
    EXPECT_EQ(second.models[0].format, Model::Format::Raw);  // the 3ds model is now RAW

    // Saving the reloaded scene gives the same files again.
    saveSceneXml(second, dir.path("again/scene.xml"));
    EXPECT_EQ(readInputFile(dir.path("again/scene.xml")), readInputFile(dir.path("out/scene.xml")));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path("out/scene")), {}), 2);  // no temporaries
}

TEST(XmlWriter, StandardOutputHoldsEveryModelInline) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    const Scene first = loadTestScene(dir);
    const std::string xml = savedToStdout(first);
    EXPECT_EQ(xml.find("file="), std::string::npos);
    EXPECT_NE(xml.find("encoding=\"base64\""), std::string::npos);
    expectSameScene(first, loadSceneXmlFromString(xml, "<stdin>", dir.path("nowhere")));
}

TEST(XmlWriter, InstancesWithoutTransformHaveNoMatrix) {
    Scene scene;
    scene.models.push_back(rawModel({}, {0, 0, 0, 1}));
    scene.models[0].name = "m";
    scene.materials.push_back(Material{});
    scene.instances.push_back({0, 0, Transform()});
    scene.instances.push_back({0, 0, Transform::translate({1, 2, 3})});
    scene.flatten();
    const std::string xml = savedToStdout(scene);
    EXPECT_NE(xml.find("<matrix m=\"1 0 0 1 0 1 0 2 0 0 1 3\">"), std::string::npos) << xml;
    EXPECT_EQ(xml.find("<matrix"), xml.rfind("<matrix"));  // only one
}

TEST(XmlWriter, NamesAreMadeUniqueAndSafe) {
    TempDir dir;
    Scene scene;
    for (const char* name : {"a/b c", "A/B C", "", "..", "a/b c"}) {
        scene.models.push_back(rawModel({}, {0, 0, 0, 1}));
        scene.models.back().name = name;
        scene.instances.push_back({std::uint32_t(scene.models.size() - 1), 0, Transform()});
    }
    scene.materials.resize(2);  // both unnamed
    scene.flatten();
    saveSceneXml(scene, dir.path("s.xml"));
    for (const char* file : {"a_b_c.raw", "A_B_C_2.raw", "model.raw", "_..raw", "a_b_c_3.raw"})
        EXPECT_TRUE(std::filesystem::is_regular_file(dir.path("s/") + file)) << file;
    const Scene back = loadSceneXml(dir.path("s.xml"));
    EXPECT_EQ(back.models[4].name, "a/b c_2");
    EXPECT_EQ(back.materials[1].name, "material_2");
    expectSamePrimitives(scene.primitives, back.primitives);
}

TEST(XmlWriter, EveryCameraIsWrittenTheFirstFirstAndAllNamed) {
    Scene scene;
    scene.camera.name = "main";
    scene.camera.focalDistance = 700;
    for (const char* name : {"", "main"}) {
        scene.extraCameras.emplace_back().name = name;
        scene.extraCameras.back().origin = {1, 2, 3};
    }
    const Scene back = loadSceneXmlFromString(savedToStdout(scene), "<stdin>", ".");
    EXPECT_EQ(back.camera.name, "main");
    EXPECT_EQ(back.camera.focalDistance, Real(700));
    ASSERT_EQ(back.extraCameras.size(), 2u);
    EXPECT_EQ(back.extraCameras[0].name, "camera");  // several cameras: each can be picked by name
    EXPECT_EQ(back.extraCameras[1].name, "main_2");
    EXPECT_EQ(back.extraCameras[1].origin, Vec3(1, 2, 3));
    Scene one;  // one unnamed camera stays unnamed, as the thesis wrote it
    EXPECT_EQ(savedToStdout(one).find("name="), std::string::npos);
}

TEST(XmlWriter, ModelFolderFollowsTheXmlName) {
    EXPECT_EQ(modelFolderFor("out/scene.xml"), "out/scene");
    EXPECT_EQ(modelFolderFor("scene"), "scene.models");
}

// Textures, material textures, emission, cut-outs and normal maps, and RAW per-corner sections survive a save and a
// load; an image's file is written relative to the new scene's folder.
TEST(XmlWriter, MaterialTexturesAndVertexDataRoundTrip) {
    TempDir dir;
    const std::string xml = R"(<scene><camera><origin z="-5"/><destination/></camera>
      <textures>
        <texture name="wood" file="pictures/wood.png" wrap_s="clamp" wrap_t="mirror" offset="0.5 0.25" scale="2 3" rotation="0.5"/>
        <texture name="floor" type="checker" color_a="1 0.5 0" color_b="0 0 0.25" size="0.5"/>
      </textures>
      <materials>
        <material name="lamp" texture="floor" emission="2 1 0.5" emission_texture="wood"
                  alpha_cutoff="0.25" alpha="0.75" alpha_texture="wood" normal_texture="wood" normal_scale="0.5"/>
      </materials></scene>)";
    Scene first = loadSceneXml(dir.write("in/scene.xml", xml));
    Model m;
    m.name = "smooth";
    m.triangleVertices = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    m.vertexNormals = {0, 0, 1, 0, 0.6f, 0.8f, 0, 0, 1};
    m.vertexUvs = {0, 0, 1, 0, 0, 1};
    first.models.push_back(m);
    first.instances.push_back({0, 0, Transform()});
    saveSceneXml(first, dir.path("out/deeper/scene.xml"));
    const Scene second = loadSceneXml(dir.path("out/deeper/scene.xml"));
    ASSERT_EQ(second.textures.size(), 2u);
    const Texture& wood = second.textures[0];
    EXPECT_EQ(wood.file, "../../in/pictures/wood.png");
    EXPECT_EQ(std::filesystem::weakly_canonical(wood.path),
              std::filesystem::weakly_canonical(dir.path("in/pictures/wood.png")));
    EXPECT_EQ(wood.wrapS, Texture::Wrap::Clamp);
    EXPECT_EQ(wood.wrapT, Texture::Wrap::Mirror);
    EXPECT_EQ(wood.offset, (std::array<float, 2>{0.5f, 0.25f}));
    EXPECT_EQ(wood.scale, (std::array<float, 2>{2, 3}));
    EXPECT_EQ(wood.rotation, 0.5f);
    const Texture& floor = second.textures[1];
    EXPECT_EQ(floor.kind, Texture::Kind::Checker);
    EXPECT_EQ(floor.colorA, (Color{1, 0.5f, 0}));
    EXPECT_EQ(floor.colorB, (Color{0, 0, 0.25f}));
    EXPECT_EQ(floor.size, 0.5f);
    const Material& lamp = second.materials[0];
    EXPECT_EQ(lamp.colorTexture, std::optional<std::uint32_t>(1));
    EXPECT_EQ(lamp.emission.color, (Color{2, 1, 0.5f}));
    EXPECT_EQ(lamp.emission.texture, std::optional<std::uint32_t>(0));
    EXPECT_EQ(lamp.opacity.cutoff, std::optional<float>(0.25f));
    EXPECT_EQ(lamp.opacity.alpha, 0.75f);
    EXPECT_EQ(lamp.opacity.texture, std::optional<std::uint32_t>(0));
    EXPECT_EQ(lamp.normalMap.texture, std::optional<std::uint32_t>(0));
    EXPECT_EQ(lamp.normalMap.scale, 0.5f);
    ASSERT_EQ(second.models.size(), 1u);
    EXPECT_EQ(second.models[0].vertexNormals, m.vertexNormals);
    EXPECT_EQ(second.models[0].vertexUvs, m.vertexUvs);
    EXPECT_TRUE(second.models[0].vertexColors.empty());
}

// An image the scene holds itself (embedded in a .glb) is written as a file into the models'
// folder and named from the XML; on standard output it goes inline, as models do, and reads
// back as the same bytes.
TEST(XmlWriter, EmbeddedImagesBecomeFilesOrInlineData) {
    TempDir dir;
    Scene first;
    const std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', 1, 2, 3, 0, 255};
    for (const char* name : {"Duck.png", "duck.png"}) {  // the same name, ignoring case
        Texture t;
        t.name = "t";
        t.file = name;
        t.embedded = std::make_shared<const std::vector<std::uint8_t>>(png);
        first.textures.push_back(t);
    }
    saveSceneXml(first, dir.path("out/scene.xml"));
    const Scene second = loadSceneXml(dir.path("out/scene.xml"));
    ASSERT_EQ(second.textures.size(), 2u);
    EXPECT_EQ(second.textures[0].file, "scene/Duck.png");
    EXPECT_EQ(second.textures[1].file, "scene/duck_2.png");
    for (const Texture& t : second.textures) {
        EXPECT_FALSE(t.embedded);
        std::ifstream in(t.path, std::ios::binary);
        EXPECT_EQ(std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {}), png) << t.path;
    }
    const Scene piped = loadSceneXml(dir.write("piped.xml", savedToStdout(first)));
    ASSERT_EQ(piped.textures.size(), 2u);
    ASSERT_TRUE(piped.textures[1].embedded);
    EXPECT_EQ(*piped.textures[1].embedded, png);
    EXPECT_EQ(piped.textures[1].file, "duck.png");
    EXPECT_TRUE(piped.textures[1].path.empty());
}

TEST(XmlLoader, UnknownTexturesAndTypesAreErrors) {
    TempDir dir;
    const auto error = [&](const std::string& body) {
        return inputErrorOf([&] {
            loadSceneXml(
                dir.write("s.xml", "<scene><camera><origin z=\"-5\"/><destination/></camera>" + body + "</scene>"));
        });
    };
    EXPECT_EQ(error("<materials><material name=\"m\" texture=\"none\"/></materials>"),
              dir.path("s.xml") + ":1: unknown texture 'none'");
    EXPECT_EQ(error("<textures><texture name=\"t\" type=\"noise\"/></textures>"),
              dir.path("s.xml") + ":1: unknown texture type 'noise' (image or checker)");
    EXPECT_EQ(error("<textures><texture name=\"t\" file=\"a.png\" wrap=\"tile\"/></textures>"),
              dir.path("s.xml") + ":1: unknown wrap 'tile' (repeat, clamp or mirror)");
}

// The path tracer's metallic-roughness factors survive a save and a load; a material without
// them gets none (the path tracer then derives them), and one factor alone takes glTF's
// defaults for the others.
TEST(XmlWriter, MetallicRoughnessFactorsRoundTrip) {
    TempDir dir;
    const std::string xml = R"(<scene><camera><origin z="-5"/><destination/></camera>
      <materials>
        <material name="gold" metallic="1" roughness="0.25" specular_factor="0.5"/>
        <material name="rough" roughness="0.75"/>
        <material name="thesis"/>
      </materials></scene>)";
    const Scene first = loadSceneXml(dir.write("scene.xml", xml));
    saveSceneXml(first, dir.path("out.xml"));
    const Scene second = loadSceneXml(dir.path("out.xml"));
    ASSERT_EQ(second.materials.size(), 3u);
    ASSERT_TRUE(second.materials[0].pbr.factors);
    EXPECT_EQ(second.materials[0].pbr.factors->metallic, 1.0f);
    EXPECT_EQ(second.materials[0].pbr.factors->roughness, 0.25f);
    EXPECT_EQ(second.materials[0].pbr.factors->specular, 0.5f);
    ASSERT_TRUE(second.materials[1].pbr.factors);
    EXPECT_EQ(second.materials[1].pbr.factors->metallic, 1.0f);
    EXPECT_EQ(second.materials[1].pbr.factors->roughness, 0.75f);
    EXPECT_FALSE(second.materials[2].pbr.factors);
    const std::string error = inputErrorOf([&] {
        loadSceneXml(dir.write("bad.xml", R"(<scene><camera><origin z="-5"/><destination/></camera>
            <materials><material name="m" metallic="1.5"/></materials></scene>)"));
    });
    EXPECT_NE(error.find("metallic must be between 0 and 1"), std::string::npos) << error;
}

// The clear coat (rt extension, KHR_materials_clearcoat) survives a save and a load; a material
// without one writes none, and a weight beyond 1 is an error naming the attribute.
TEST(XmlWriter, ClearcoatRoundTrips) {
    TempDir dir;
    const std::string xml = R"(<scene><camera><origin z="-5"/><destination/></camera>
      <materials>
        <material name="paint" clearcoat="0.75" clearcoat_roughness="0.125"/>
        <material name="plain"/>
      </materials></scene>)";
    const Scene first = loadSceneXml(dir.write("scene.xml", xml));
    saveSceneXml(first, dir.path("out.xml"));
    std::ifstream written(dir.path("out.xml"));
    const std::string text{std::istreambuf_iterator<char>(written), {}};
    EXPECT_EQ(text.find("clearcoat=\""), text.rfind("clearcoat=\"")) << "the plain material writes none";
    const Scene second = loadSceneXml(dir.path("out.xml"));
    ASSERT_EQ(second.materials.size(), 2u);
    EXPECT_EQ(second.materials[0].clearcoat.weight, 0.75f);
    EXPECT_EQ(second.materials[0].clearcoat.roughness, 0.125f);
    EXPECT_EQ(second.materials[1].clearcoat.weight, 0.0f);
    const std::string error = inputErrorOf([&] {
        loadSceneXml(dir.write("bad.xml", R"(<scene><camera><origin z="-5"/><destination/></camera>
            <materials><material name="m" clearcoat="2"/></materials></scene>)"));
    });
    EXPECT_NE(error.find("clearcoat must be between 0 and 1"), std::string::npos) << error;
}

// Glass (rt extension) survives a save and a load; an opaque material writes none of its
// attributes, so that thesis scenes are written as before.
TEST(XmlWriter, TransmissionRoundTripsAndOpaqueMaterialsWriteNone) {
    const std::string xml = R"(<scene><camera><origin z="-5"/><destination/></camera>
      <materials>
        <material name="glass" transmission="0.9" transmission_color="1 0.5 0.25" ior="1.33"
                  attenuation_color="0.5 0.75 1" attenuation_distance="2"/>
        <material name="sheet" transmission="0.5" thin="true"/>
        <material name="plain"/>
      </materials></scene>)";
    const Scene first = loadSceneXmlFromString(xml, "<stdin>", ".");
    const std::string saved = savedToStdout(first);
    const Scene back = loadSceneXmlFromString(saved, "<stdin>", ".");
    ASSERT_EQ(back.materials.size(), 3u);
    const Transmission& glass = back.materials[0].transmission;
    EXPECT_EQ(glass.weight, 0.9f);
    EXPECT_EQ(glass.color, (Color{1, 0.5f, 0.25f}));
    EXPECT_EQ(glass.ior, 1.33f);
    EXPECT_FALSE(glass.thin);
    EXPECT_EQ(glass.attenuationColor, (Color{0.5f, 0.75f, 1}));
    EXPECT_EQ(glass.attenuationDistance, 2.0f);
    EXPECT_TRUE(glass.absorbs());
    const Transmission& sheet = back.materials[1].transmission;
    EXPECT_TRUE(sheet.thin);
    EXPECT_EQ(sheet.ior, 1.5f);  // the default, glass
    EXPECT_FALSE(sheet.absorbs());
    EXPECT_FALSE(back.materials[2].transmission.passesLight());
    Scene opaque;
    opaque.materials.push_back({.name = "m", .phong = {.reflection = 0.5f}});
    const std::string plain = savedToStdout(opaque);
    for (const char* attribute : {"transmission", "ior", "thin", "attenuation"})
        EXPECT_EQ(plain.find(attribute), std::string::npos) << attribute;
}

// A single-sided material (rt extension, glTF's doubleSided false) survives a save and a load;
// a two-sided one, the default and every thesis material, writes nothing.
TEST(XmlWriter, SingleSidedMaterialsRoundTripAndTwoSidedWriteNothing) {
    const std::string xml = R"(<scene><camera><origin z="-5"/><destination/></camera>
      <materials>
        <material name="leaf" double_sided="false"/>
        <material name="both" double_sided="true"/>
        <material name="thesis"/>
      </materials></scene>)";
    const Scene first = loadSceneXmlFromString(xml, "<stdin>", ".");
    ASSERT_EQ(first.materials.size(), 3u);
    EXPECT_FALSE(first.materials[0].doubleSided);
    EXPECT_TRUE(first.materials[1].doubleSided);
    EXPECT_TRUE(first.materials[2].doubleSided);
    const std::string saved = savedToStdout(first);
    EXPECT_EQ(saved.find("double_sided"), saved.rfind("double_sided")) << "written once, for the leaf:\n" << saved;
    const Scene back = loadSceneXmlFromString(saved, "<stdin>", ".");
    ASSERT_EQ(back.materials.size(), 3u);
    EXPECT_FALSE(back.materials[0].doubleSided);
    EXPECT_TRUE(back.materials[1].doubleSided);
    EXPECT_TRUE(back.materials[2].doubleSided);
    EXPECT_EQ(inputErrorOf([&] {
                  loadSceneXmlFromString(R"(<scene><camera><origin z="-5"/><destination/></camera>
                      <materials><material name="m" double_sided="no"/></materials></scene>)",
                                         "s.xml", ".");
              }),
              "s.xml:2: <material> double_sided must be true or false");
}

TEST(XmlLoader, BadTransmissionValuesAreErrors) {
    const auto error = [&](const std::string& attributes) {
        return inputErrorOf([&] {
            loadSceneXmlFromString(
                "<scene><camera><origin z=\"-5\"/><destination/></camera><materials><material "
                "name=\"m\" " +
                    attributes + "/></materials></scene>",
                "s.xml", ".");
        });
    };
    EXPECT_EQ(error("transmission=\"1.5\""), "s.xml:1: <material> transmission must be between 0 and 1");
    EXPECT_EQ(error("thin=\"yes\""), "s.xml:1: <material> thin must be true or false");
    EXPECT_EQ(error("ior=\"0\""), "s.xml:1: <material> attribute 'ior' must be positive");
    EXPECT_EQ(error("attenuation_distance=\"-1\""),
              "s.xml:1: <material> attribute 'attenuation_distance' must be positive");
}

// The path tracer's sky (rt extension): an image <texture> named by <environment>, with its
// intensity and rotation, survives a save and a load; a scene without one writes none.
TEST(XmlWriter, EnvironmentRoundTrips) {
    const std::string xml = R"(<scene><camera><origin z="-5"/><destination/></camera>
      <environment texture="sky" intensity="2.5" rotation="-90"/>
      <textures><texture name="checks" type="checker"/><texture name="sky" file="skies/sky.exr"/></textures>
      </scene>)";
    const Scene first = loadSceneXmlFromString(xml, "<stdin>", "/scenes");
    ASSERT_TRUE(first.environment);
    EXPECT_EQ(first.environment->texture, 1u);
    EXPECT_EQ(first.textures[1].path, "/scenes/skies/sky.exr") << "relative to the scene";
    const Scene back = loadSceneXmlFromString(savedToStdout(first), "<stdin>", "/scenes");
    ASSERT_TRUE(back.environment);
    EXPECT_EQ(back.textures.at(back.environment->texture).path, "/scenes/skies/sky.exr");
    EXPECT_EQ(back.environment->intensity, 2.5f);
    EXPECT_EQ(back.environment->rotation, -90.0f);
    Scene none;
    EXPECT_EQ(savedToStdout(none).find("environment"), std::string::npos);
}

// A headlight is written without a position and read back at the camera: the scene's, then the
// one --camera picks (issue 36: the default light belongs to the camera rendered).
TEST(XmlWriter, HeadlightRoundTripsAtTheCamera) {
    const std::string xml = R"(<scene><camera><origin z="-5"/><destination/></camera>
      <camera name="top"><origin y="7"/><destination/><up z="1"/></camera>
      <lights><light headlight="true" r="0.5" g="0.5" b="0.5"/><light x="1" y="2" z="3"/></lights></scene>)";
    Scene first = loadSceneXmlFromString(xml, "<stdin>", ".");
    ASSERT_EQ(first.lights.size(), 2u);
    EXPECT_TRUE(first.lights[0].headlight);
    EXPECT_EQ(first.lights[0].position, Vec3(0, 0, -5));
    EXPECT_FALSE(first.lights[1].headlight);
    const std::string saved = savedToStdout(first);
    EXPECT_NE(saved.find(R"(<light headlight="true" r="0.5")"), std::string::npos) << saved;
    Scene back = loadSceneXmlFromString(saved, "<stdin>", ".");
    EXPECT_TRUE(back.lights[0].headlight);
    EXPECT_EQ(back.lights[0].position, Vec3(0, 0, -5));
    back.selectCamera("top");
    EXPECT_EQ(back.lights[0].position, Vec3(0, 7, 0));
    EXPECT_EQ(back.lights[1].position, Vec3(1, 2, 3)) << "other lights stay";
    back.camera.origin = {4, 4, 4};
    back.placeHeadlights();
    EXPECT_EQ(back.lights[0].position, Vec3(4, 4, 4));
    back.dropHeadlights();
    ASSERT_EQ(back.lights.size(), 1u);
    EXPECT_FALSE(back.lights[0].headlight);
}

TEST(XmlLoader, BadEnvironmentsAreErrors) {
    const auto error = [&](const std::string& body) {
        return inputErrorOf([&] {
            loadSceneXmlFromString("<scene><camera><origin z=\"-5\"/><destination/></camera>\n" + body + "</scene>",
                                   "s.xml", ".");
        });
    };
    EXPECT_EQ(error("<environment texture=\"sky\"/>"), "s.xml:2: unknown texture 'sky'");
    EXPECT_EQ(error("<environment texture=\"c\"/><textures><texture name=\"c\" type=\"checker\"/></textures>"),
              "s.xml:2: the environment's texture must be an image");
    EXPECT_EQ(error("<environment texture=\"s\" intensity=\"-1\"/>"),
              "s.xml:2: <environment> attribute 'intensity' must not be negative");
    EXPECT_EQ(error("<environment/>"), "s.xml:2: <environment> needs attribute 'texture'");
    EXPECT_EQ(error("<environment texture=\"a\"/><environment texture=\"a\"/>"),
              "s.xml:2: a second <environment> in <scene>");
}
