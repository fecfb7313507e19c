// glTF import (libtrace/import/gltf_import.*): the shared glTF and GLB models against the
// Assimp figures of MANIFEST.md, instancing, hierarchy, cameras, lights, and one broken
// rule at a time in small generated files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"
#include "import/import.h"
#include "import_test_util.h"
#include "scene/base64.h"
#include "test_util.h"

namespace rt {
namespace {

using test::GltfFixture;
using test::replaceOnce;
using test::sharedModels;
using test::TempDir;

constexpr Real kLoose = Real(1e-4);  // float data, either Real

// Every glTF and GLB model the manifest lists, however many there are.
TEST(ImportGltf, TriangleCountsMatchTheManifest) {
    SKIP_WITHOUT_SHARED_MODELS();
    EXPECT_EQ(test::expectManifestTriangleCounts({"gltf", "glb"}, [](const ImportResult&) {}),
              test::manifestModelFolders("gltf") + test::manifestModelFolders("glb"));
}

// Assimp's FindDegenerates (its "assimp info" column) finds exactly the triangles dropped here.
TEST(ImportGltf, DegenerateTrianglesAreTheOnesAssimpFinds) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult engine = importScene(sharedModels() + "/glb/2CylinderEngine/2CylinderEngine.glb");
    EXPECT_EQ(test::modelTriangles(engine.scene), 65311u);
    EXPECT_EQ(engine.report.droppedDegenerate, 75730u - 65311u);
}

TEST(ImportGltf, ASharedMeshIsOneModelWithSeveralInstances) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/SharedMesh/02_shared_mesh.gltf");
    ASSERT_EQ(r.scene.models.size(), 1u);
    ASSERT_EQ(r.scene.instances.size(), 2u);
    EXPECT_EQ(r.scene.instances[0].model, r.scene.instances[1].model);
    EXPECT_FALSE(r.scene.instances[0].transform == r.scene.instances[1].transform);
    EXPECT_EQ(r.report.meshes, 1u);
}

// 29 meshes with 34 primitives, placed 115 times: one model per primitive, not per placement.
TEST(ImportGltf, TheEngineKeepsOneModelPerPrimitive) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/glb/2CylinderEngine/2CylinderEngine.glb");
    EXPECT_EQ(r.report.meshes, 29u);
    EXPECT_EQ(r.scene.models.size(), 34u);
    EXPECT_EQ(r.scene.instances.size(), 115u);
    std::set<std::string> names;
    for (const Model& m : r.scene.models) names.insert(m.name);
    EXPECT_EQ(names.size(), r.scene.models.size()) << "model names must be unique: they name the RAW files";
}

// Cameras.gltf: the perspective camera is node 1 at (0.5, 0.5, 3) looking down -z with
// yfov 0.7 and aspect 1, so the horizontal fov is 0.7 rad as well.
TEST(ImportGltf, CameraLandsWhereTheNodePutsIt) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/Cameras/Cameras.gltf");
    const Camera& c = r.scene.camera;
    expectNear(c.origin, {0.5, 0.5, 3}, kLoose);
    expectNear(normalize(c.destination - c.origin), {0, 0, -1}, kLoose);
    expectNear(c.up, {0, 1, 0}, kLoose);
    ASSERT_TRUE(c.fovDegrees);
    EXPECT_NEAR(*c.fovDegrees, 0.7 * 180 / kPi, 1e-3);
    EXPECT_EQ(r.report.cameraUsed, "#0");
    EXPECT_FALSE(r.report.cameraGenerated);
    EXPECT_TRUE(r.report.lightGenerated);  // the file has no light
}

TEST(ImportGltf, AnOrthographicCameraIsRefusedByName) {
    SKIP_WITHOUT_SHARED_MODELS();
    ImportOptions o;
    o.camera = "1";
    EXPECT_THROW(importScene(sharedModels() + "/gltf/Cameras/Cameras.gltf", o), InputError);
    o.camera = "nonesuch";
    EXPECT_THROW(importScene(sharedModels() + "/gltf/Cameras/Cameras.gltf", o), InputError);
}

// Every perspective camera a node places is kept, the one taken first: rt-render --camera
// picks among them after the conversion.
TEST(ImportGltf, EveryPerspectiveCameraIsKeptTheChosenFirst) {
    TempDir dir;
    GltfFixture f;
    f.nodes = R"([{"mesh": 0, "children": [1, 2, 3]}, {"camera": 0, "translation": [0, 0, 5]},
                  {"camera": 1, "translation": [5, 0, 0]}, {"camera": 2}])";
    f.extra = R"(, "cameras": [{"type": "perspective", "name": "front", "perspective": {"yfov": 0.5, "znear": 0.1}},
        {"type": "perspective", "name": "side", "perspective": {"yfov": 0.7, "aspectRatio": 1, "znear": 0.1}},
        {"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}])";
    const std::string path = dir.write("cameras.gltf", f.json());
    const ImportResult first = importScene(path);
    EXPECT_EQ(first.scene.camera.name, "front");
    ASSERT_EQ(first.scene.extraCameras.size(), 1u);
    EXPECT_EQ(first.scene.extraCameras[0].name, "side");
    expectNear(first.scene.extraCameras[0].origin, {5, 0, 0}, kLoose);
    EXPECT_NEAR(*first.scene.extraCameras[0].fovDegrees, 0.7 * 180 / kPi, 1e-3);
    ImportOptions o;
    o.camera = "side";
    const ImportResult side = importScene(path, o);
    EXPECT_EQ(side.scene.camera.name, "side");
    ASSERT_EQ(side.scene.extraCameras.size(), 1u);
    EXPECT_EQ(side.scene.extraCameras[0].name, "front");
}

// issue-261.gltf: camera and point light under matrix transforms; the light's intensity 1000
// becomes colour 1 (rt lights have no falloff, only ratios are kept).
TEST(ImportGltf, PointLightAndCameraOfIssue261) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/PointLightCamera-issue261/issue-261.gltf");
    const Camera& c = r.scene.camera;
    expectNear(c.origin, {0.9729073377709113, 1.2592438262175363, 2.419918748461627}, kLoose);
    expectNear(normalize(c.destination - c.origin), {-0.290254840694694, -0.48551237507207207, -0.8246392308792816},
               kLoose);
    // yfov 0.9273 (tan of half = 0.5) and aspect 4/3: tan of half the horizontal fov = 2/3.
    EXPECT_NEAR(std::tan(*c.fovDegrees * kPi / 360), 2.0 / 3.0, 1e-5);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    expectNear(r.scene.lights[0].position, {2.3640632834071384, 2.465226204472449, 2.309515908392224}, kLoose);
    EXPECT_EQ(r.scene.lights[0].color, Color(1, 1, 1));
    EXPECT_FALSE(r.report.lightGenerated);
    EXPECT_EQ(r.report.cameraUsed, "default");
}

// Spot and directional lights become point lights, each approximation noted.
TEST(ImportGltf, SpotAndDirectionalLightsAreApproximated) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/AnimateAllTheThings/24_animation_pointer.gltf");
    EXPECT_EQ(r.scene.lights.size(), 4u);
    std::size_t approximations = 0;
    for (const std::string& n : r.report.notes) approximations += n.find("approximated") != std::string::npos;
    EXPECT_EQ(approximations, 4u);
    float peak = 0;
    for (const Light& l : r.scene.lights) peak = std::max({peak, l.color.r, l.color.g, l.color.b});
    EXPECT_FLOAT_EQ(peak, 1.0f);
}

TEST(ImportGltf, PointsAndLinesAreSkippedAndCounted) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/MeshPrimitiveModes/MeshPrimitiveModes.gltf");
    EXPECT_EQ(r.report.droppedPoints, 1u);
    EXPECT_EQ(r.report.droppedLines, 3u);
    EXPECT_EQ(r.scene.models.size(), 3u);  // triangles, strip, fan
}

TEST(ImportGltf, WithoutCameraAndLightTheSceneIsFramed) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/gltf/Box/Box.gltf");
    EXPECT_TRUE(r.report.cameraGenerated);
    EXPECT_TRUE(r.report.lightGenerated);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    // The unit box centred at the origin is in front of the camera and inside its view cone.
    const Camera& c = r.scene.camera;
    const Vec3 view = normalize(c.destination - c.origin);
    const Vec3 toCentre = Vec3(0, 0, 0) - c.origin;
    EXPECT_GT(dot(toCentre, view) / length(toCentre), std::cos(25 * kPi / 180));
    EXPECT_GT(length(toCentre), 0.87);  // outside the box's bounding sphere
}

// Node 0 translates by (1, 0, 0) and turns 90 degrees about y; its child scales by 2.
// A vertex (1, 0, 0) of the child's mesh lands at parent * child * v = (1, 0, -2).
TEST(ImportGltf, HierarchyComposesParentTimesLocal) {
    TempDir dir;
    GltfFixture f;
    const double s = std::sqrt(0.5);
    f.nodes = R"([{"translation": [1, 0, 0], "rotation": [0, )" + std::to_string(s) + ", 0, " + std::to_string(s) +
              R"(], "children": [1]}, {"scale": [2, 2, 2], "mesh": 0}])";
    ImportResult r = importScene(dir.write("h.gltf", f.json()));
    ASSERT_EQ(r.scene.instances.size(), 1u);
    r.scene.flatten();
    const Triangle t = r.scene.primitives.all<Triangle>()[0];
    expectNear(t.p0, {1, 0, 0}, kLoose);
    expectNear(t.p1, {1, 0, -2}, kLoose);
    expectNear(t.p2, {1, 2, 0}, kLoose);
}

TEST(ImportGltf, ScaleAndUpAxisApplyAtTheRoot) {
    TempDir dir;
    const std::string path = dir.write("z.gltf", GltfFixture().json());
    ImportOptions o;
    o.scale = 3;
    o.upAxis = UpAxis::Z;
    ImportResult r = importScene(path, o);
    r.scene.flatten();
    const Triangle t = r.scene.primitives.all<Triangle>()[0];
    expectNear(t.p1, {3, 0, 0}, kLoose);
    expectNear(t.p2, {0, 0, -3}, kLoose);  // +y of a Z-up file points away from the viewer
}

TEST(ImportGltf, StripsAndFansAreUnrolled) {
    TempDir dir;
    GltfFixture f;
    f.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1.5f, 0};
    f.indices = {0, 1, 2, 3, 4};
    f.mode = 5;
    EXPECT_EQ(test::modelTriangles(importScene(dir.write("strip.gltf", f.json())).scene), 3u);
    f.mode = 6;
    EXPECT_EQ(test::modelTriangles(importScene(dir.write("fan.gltf", f.json())).scene), 3u);
}

// KHR_materials_ior and KHR_materials_specular reach the Phong mapping; a non-number is an error.
TEST(ImportGltf, MaterialExtensionsAreRead) {
    TempDir dir;
    GltfFixture f;
    f.extra = R"(, "materials": [{"name": "glass", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.25, 1, 1],)"
              R"( "metallicFactor": 0}, "extensions": {"KHR_materials_ior": {"ior": 2},)"
              R"( "KHR_materials_specular": {"specularFactor": 0.5}}}])";
    const std::string json = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 0)");
    const ImportResult r = importScene(dir.write("m.gltf", json));
    ASSERT_EQ(r.scene.materials.size(), 1u);
    const Material& m = r.scene.materials[0];
    EXPECT_EQ(m.name, "glass");
    EXPECT_EQ(m.color, Color(0.5f, 0.25f, 1));
    EXPECT_NEAR(m.specular, 0.5f / 9, 1e-6);  // ((2 - 1) / (2 + 1))^2 * 0.5
    EXPECT_THROW(importScene(dir.write("bad.gltf", replaceOnce(json, R"("ior": 2)", R"("ior": "two")"))), InputError);
}

// MASK cuts out at alphaCutoff of the base colour's alpha; BLEND is MASK at 0.5, with a note;
// OPAQUE (the default) is no cut-out.
TEST(ImportGltf, AlphaModesBecomeCutouts) {
    TempDir dir;
    GltfFixture f;
    const auto material = [&](const std::string& mode) {
        f.extra = R"(, "materials": [{"name": "leaf", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.5]})" +
                  mode + "}]";
        const std::string json = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 0)");
        return importScene(dir.write("m.gltf", json));
    };
    const ImportResult mask = material(R"(, "alphaMode": "MASK", "alphaCutoff": 0.25)");
    EXPECT_EQ(mask.scene.materials[0].alphaCutoff, std::optional<float>(0.25f));
    EXPECT_EQ(mask.scene.materials[0].alpha, 0.5f);
    const ImportResult blend = material(R"(, "alphaMode": "BLEND")");
    EXPECT_EQ(blend.scene.materials[0].alphaCutoff, std::optional<float>(0.5f));
    const auto& notes = blend.report.notes;
    EXPECT_TRUE(std::any_of(notes.begin(), notes.end(),
                            [](const std::string& n) { return n.find("alphaMode BLEND") != std::string::npos; }));
    EXPECT_FALSE(material("").scene.materials[0].alphaCutoff);
}

// KHR_materials_transmission, _ior and _volume make glass tinted by the base colour; without a
// volume (or of thickness 0) it is thin-walled; the transmitted share no longer scatters.
TEST(ImportGltf, TransmissionAndVolumeMakeGlass) {
    TempDir dir;
    GltfFixture f;
    f.extra =
        R"(, "materials": [{"name": "glass", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.7, 0.9, 1],)"
        R"( "metallicFactor": 0, "roughnessFactor": 0}, "extensions": {"KHR_materials_ior": {"ior": 1.33},)"
        R"( "KHR_materials_transmission": {"transmissionFactor": 1}, "KHR_materials_volume": {"thicknessFactor": 0.5,)"
        R"( "attenuationColor": [0.5, 0.25, 1], "attenuationDistance": 2}}},)"
        R"( {"name": "sheet", "pbrMetallicRoughness": {"metallicFactor": 0},)"
        R"( "extensions": {"KHR_materials_transmission": {"transmissionFactor": 0.5}}},)"
        R"( {"name": "paper", "pbrMetallicRoughness": {"metallicFactor": 0}, "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1,)"
        R"( "transmissionTexture": {"index": 0}}}}])";
    const std::string one = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 0)");
    const Material glass = importScene(dir.write("glass.gltf", one)).scene.materials.at(0);
    EXPECT_EQ(glass.transmission.weight, 1.0f);
    EXPECT_EQ(glass.transmission.color, Color(0.5f, 0.7f, 0.9f));
    EXPECT_EQ(glass.transmission.ior, 1.33f);
    EXPECT_FALSE(glass.transmission.thin);
    EXPECT_EQ(glass.transmission.attenuationColor, Color(0.5f, 0.25f, 1));
    EXPECT_EQ(glass.transmission.attenuationDistance, 2.0f);
    EXPECT_EQ(glass.diffuse, 0.0f);
    EXPECT_EQ(glass.ambient, 0.0f);
    EXPECT_EQ(glass.reflection, 0.0f) << "the renderer's Fresnel term reflects";
    const std::string two = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 1)");
    const Material sheet = importScene(dir.write("sheet.gltf", two)).scene.materials.at(0);
    EXPECT_EQ(sheet.transmission.weight, 0.5f);
    EXPECT_TRUE(sheet.transmission.thin);
    EXPECT_FLOAT_EQ(sheet.diffuse, 0.45f);
    const std::string three = replaceOnce(f.json(), R"("mode": 4)", R"("mode": 4, "material": 2)");
    const Material paper = importScene(dir.write("paper.gltf", three)).scene.materials.at(0);
    EXPECT_EQ(paper.transmission.weight, 0.5f) << "a transmission texture is taken as mid-grey";
    EXPECT_THROW(importScene(dir.write(
                     "bad.gltf", replaceOnce(one, R"("transmissionFactor": 1)", R"("transmissionFactor": "all")"))),
                 InputError);
}

TEST(ImportGltf, ChoosesTheSceneAndRejectsAMissingOne) {
    TempDir dir;
    const std::string path = dir.write("s.gltf", GltfFixture().json());
    ImportOptions o;
    o.scene = 0;
    EXPECT_NO_THROW(importScene(path, o));
    o.scene = 1;
    EXPECT_THROW(importScene(path, o), InputError);
}

// Each broken rule is one clear InputError, never a crash or an out-of-bounds read.
struct BrokenRule {
    const char* name;
    const char* from;
    const char* to;
};

class ImportGltfBroken : public ::testing::TestWithParam<BrokenRule> {};

TEST_P(ImportGltfBroken, IsAnInputError) {
    TempDir dir;
    const std::string json = replaceOnce(GltfFixture().json(), GetParam().from, GetParam().to);
    EXPECT_THROW(importScene(dir.write("broken.gltf", json)), InputError);
}

INSTANTIATE_TEST_SUITE_P(
    Rules, ImportGltfBroken,
    ::testing::Values(
        BrokenRule{"AccessorPastItsView", R"("count": 3, "type": "VEC3")", R"("count": 4, "type": "VEC3")"},
        BrokenRule{"AccessorOffsetPastItsView", R"("componentType": 5126,)",
                   R"("componentType": 5126, "byteOffset": 4,)"},
        BrokenRule{"StrideShorterThanAnElement", R"("byteOffset": 0, "byteLength": 36)",
                   R"("byteOffset": 0, "byteLength": 36, "byteStride": 4)"},
        BrokenRule{"ViewPastItsBuffer", R"("byteOffset": 0, "byteLength": 36)", R"("byteOffset": 8, "byteLength": 36)"},
        BrokenRule{"MissingAccessor", R"("POSITION": 0)", R"("POSITION": 7)"},
        BrokenRule{"IndicesOfFloatType", R"("componentType": 5123)", R"("componentType": 5126)"},
        BrokenRule{"PositionsAsVec2", R"("type": "VEC3")", R"("type": "VEC2")"},
        BrokenRule{"MissingMesh", R"([{"mesh": 0}])", R"([{"mesh": 3}])"},
        BrokenRule{"MissingNode", R"("nodes": [0]})", R"("nodes": [5]})"},
        BrokenRule{"NodeIsItsOwnChild", R"([{"mesh": 0}])", R"([{"mesh": 0, "children": [0]}])"},
        BrokenRule{"NodeWithTwoParents", R"([{"mesh": 0}])", R"([{"children": [1, 1]}, {"mesh": 0}])"},
        BrokenRule{"MatrixNotAffine", R"([{"mesh": 0}])",
                   R"([{"mesh": 0, "matrix": [1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1]}])"},
        BrokenRule{"UnknownMode", R"("mode": 4)", R"("mode": 9)"},
        BrokenRule{"MissingMaterial", R"("mode": 4)", R"("mode": 4, "material": 2)"},
        BrokenRule{"NoScene", R"("scene": 0, "scenes": [{"nodes": [0]}],)", ""}),
    [](const ::testing::TestParamInfo<BrokenRule>& p) { return std::string(p.param.name); });

TEST(ImportGltf, IndexOutOfRangeIsAnInputError) {
    TempDir dir;
    GltfFixture f;
    f.indices = {0, 1, 3};
    EXPECT_THROW(importScene(dir.write("i.gltf", f.json())), InputError);
}

TEST(ImportGltf, NanPositionIsAnInputError) {
    TempDir dir;
    GltfFixture f;
    f.positions[4] = std::nanf("");
    EXPECT_THROW(importScene(dir.write("nan.gltf", f.json())), InputError);
}

// A huge count with no bufferView would be all zeros: bounded by the file's data, not allocated.
TEST(ImportGltf, AHugeCountWithoutDataIsRefusedBeforeAllocating) {
    TempDir dir;
    std::string json = replaceOnce(GltfFixture().json(), R"({"bufferView": 0, "componentType": 5126, "count": 3,)",
                                   R"({"componentType": 5126, "count": 4000000000000,)");
    EXPECT_THROW(importScene(dir.write("huge.gltf", json)), InputError);
}

// A buffer URI may name files in the model's folder and below; "../" would let a model copy any
// readable file into the scene, so it needs ImportOptions::filesOutsideModelFolder.
TEST(ImportGltf, BuffersOutsideTheModelsFolderAreRefused) {
    TempDir dir;
    const std::string json = GltfFixture().json();
    const std::size_t start = json.find("data:application"), end = json.find('"', start);
    std::size_t badAt = 0;
    const auto bytes = decodeBase64(json.substr(json.find(',', start) + 1, end - json.find(',', start) - 1), badAt);
    ASSERT_TRUE(bytes);
    dir.write("outside.bin", std::string(bytes->begin(), bytes->end()));
    dir.write("model/data/inside.bin", std::string(bytes->begin(), bytes->end()));
    const auto naming = [&](const std::string& uri) {
        return dir.write("model/m.gltf", json.substr(0, start) + uri + json.substr(end));
    };
    EXPECT_NO_THROW(importScene(naming("data/inside.bin")));
    for (const std::string uri : {"../outside.bin", "data/../../outside.bin"}) {
        const std::string error = inputErrorOf([&] { importScene(naming(uri)); });
        EXPECT_NE(error.find("outside the model's folder"), std::string::npos) << uri << ": " << error;
        ImportOptions trusting;
        trusting.filesOutsideModelFolder = true;
        EXPECT_NO_THROW(importScene(naming(uri), trusting)) << uri;
    }
}

// Element 0 of the positions is replaced by the fourth point of the data, (5, 5, 5).
TEST(ImportGltf, SparseAccessorsReplaceTheirElements) {
    TempDir dir;
    GltfFixture f;
    f.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5};
    const std::string json = replaceOnce(
        f.json(), R"("count": 4, "type": "VEC3"})",
        R"("count": 4, "type": "VEC3", "sparse": {"count": 1, "indices": {"bufferView": 1, "componentType": 5123},)"
        R"( "values": {"bufferView": 0, "byteOffset": 36}}})");
    ImportResult r = importScene(dir.write("sparse.gltf", json));
    r.scene.flatten();
    expectNear(r.scene.primitives.all<Triangle>()[0].p0, {5, 5, 5}, kLoose);
}

// Debian's Assimp aborts on these two files; they must reach tinygltf whatever their name.
TEST(ImportGltf, AGlbUnderAnyNameNeverReachesAssimp) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    for (const char* name : {"CubeInvalidBufferViewLength.glb", "CubeInvalidAccessorByteOffset.glb"}) {
        std::ifstream in(sharedModels() + "/bad/glb-sdk/" + name, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_FALSE(bytes.empty());
        EXPECT_THROW(importScene(dir.write("renamed.model", bytes)), InputError);
        EXPECT_THROW(importScene(dir.write("renamed", bytes)), InputError);
    }
}

// NORMAL, TEXCOORD_0 and COLOR_0 reach the models: the Duck has normals and texture
// coordinates, VertexColorTest colours.
TEST(ImportGltf, VertexNormalsTextureCoordinatesAndColoursAreKept) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult duck = importScene(sharedModels() + "/glb/Duck/Duck.glb");
    ASSERT_EQ(duck.scene.models.size(), 1u);
    const Model& m = duck.scene.models[0];
    EXPECT_EQ(m.vertexNormals.size(), 9 * m.triangleCount());
    EXPECT_EQ(m.vertexUvs.size(), 6 * m.triangleCount());
    for (std::size_t i = 0; i < m.vertexNormals.size(); i += 3)
        EXPECT_NEAR(std::hypot(m.vertexNormals[i], m.vertexNormals[i + 1], m.vertexNormals[i + 2]), 1, 1e-5);
    const ImportResult colors = importScene(sharedModels() + "/glb/VertexColorTest/VertexColorTest.glb");
    std::size_t coloured = 0;
    for (const Model& c : colors.scene.models) coloured += !c.vertexColors.empty();
    EXPECT_GT(coloured, 0u);
}

}  // namespace
}  // namespace rt
