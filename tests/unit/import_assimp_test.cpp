// Import through Assimp (libtrace/import/assimp_import.*): the shared OBJ and 3DS models
// against the Assimp figures of MANIFEST.md, materials, cameras, and broken files.
#include <gtest/gtest.h>

#include "core/error.h"
#include "import/import.h"
#include "import_test_util.h"
#include "test_util.h"

namespace rt {
namespace {

using test::sharedModels;
using test::TempDir;

TEST(ImportAssimp, TriangleCountsMatchTheManifest) {
    const std::size_t files = test::expectManifestTriangleCounts({"obj", "3ds"}, [](const ImportResult& r) {
        EXPECT_EQ(r.scene.models.size(), r.scene.instances.size());  // these formats do not instance
    });
    EXPECT_EQ(files, 21u);
}

// spider.obj: Assimp's FindDegenerates leaves 1312 of 1368 triangles, as the dropping here does.
TEST(ImportAssimp, DegenerateTrianglesAreTheOnesAssimpFinds) {
    const ImportResult r = importScene(sharedModels() + "/obj/spider/spider.obj");
    EXPECT_EQ(test::modelTriangles(r.scene), 1312u);
    EXPECT_EQ(r.report.droppedDegenerate, 56u);
}

// CornellBox-Original.mtl: the right wall is Kd 0.14 0.45 0.091 (green) with Ns 10 and no Ks.
TEST(ImportAssimp, ObjMaterialsKeepTheirDiffuseColour) {
    const ImportResult r = importScene(sharedModels() + "/obj/CornellBox-Original/CornellBox-Original.obj");
    const std::optional<std::uint32_t> green = r.scene.findMaterial("rightWall");
    ASSERT_TRUE(green) << "materials keep their .mtl names";
    const Material& m = r.scene.materials[*green];
    EXPECT_NEAR(m.color.r, 0.14f, 1e-6);
    EXPECT_NEAR(m.color.g, 0.45f, 1e-6);
    EXPECT_NEAR(m.color.b, 0.091f, 1e-6);
    EXPECT_FLOAT_EQ(m.specular, 0);
    EXPECT_FLOAT_EQ(m.shininess, 10);
}

// A 3DS camera lands where its node puts it, looking at its target; no camera is generated.
TEST(ImportAssimp, ThreeDsCameraIsUsed) {
    const ImportResult r = importScene(sharedModels() + "/3ds/TargetCameraAnim/TargetCameraAnim.3ds");
    EXPECT_EQ(r.report.camerasInFile, 1u);
    EXPECT_FALSE(r.report.cameraGenerated);
    EXPECT_EQ(r.report.cameraUsed, "Camera01");
    const Camera& c = r.scene.camera;
    EXPECT_TRUE(isFinite(c.origin));
    EXPECT_GT(length(c.destination - c.origin), 0);
    ASSERT_TRUE(c.fovDegrees);
    EXPECT_GT(*c.fovDegrees, 0);
    EXPECT_LT(*c.fovDegrees, 180);
}

TEST(ImportAssimp, ZUpModelsAreTurnedToYUp) {
    const std::string path = sharedModels() + "/obj/box/box.obj";
    ImportResult plain = importScene(path);
    ImportOptions o;
    o.upAxis = UpAxis::Z;
    ImportResult turned = importScene(path, o);
    plain.scene.flatten();
    turned.scene.flatten();
    ASSERT_EQ(plain.scene.primitives.triangleCount(), turned.scene.primitives.triangleCount());
    const Triangle a = plain.scene.primitives.triangle(0), b = turned.scene.primitives.triangle(0);
    expectNear(b.p0, {a.p0.x, a.p0.z, -a.p0.y}, Real(1e-5));  // (x, y, z) -> (x, z, -y)
}

TEST(ImportAssimp, NanVerticesAreAnInputError) {
    EXPECT_THROW(importScene(sharedModels() + "/bad/obj-tinyobjloader/test-nan.obj"), InputError);
}

// Garbage whose keywords look like OBJ text, under a name without extension.
TEST(ImportAssimp, ContentGuessesAreOnlyTrustedForBinaryFormats) {
    EXPECT_THROW(
        importScene(sharedModels() + "/bad/assimp-fuzz/clusterfuzz-testcase-minimized-assimp_fuzzer-4751812606885888"),
        InputError);
    const ImportResult r = importScene(sharedModels() + "/3ds/testFormatDetection/testFormatDetection");
    EXPECT_EQ(r.report.format, "Discreet 3DS Importer");
}

// Assimp's glTF importers are removed: a glTF JSON under another name is unknown, not parsed.
TEST(ImportAssimp, AssimpNeverReadsGltf) {
    TempDir dir;
    std::ifstream in(sharedModels() + "/gltf/Box/Box.gltf");
    const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_THROW(importScene(dir.write("box.json", json)), InputError);
}

TEST(ImportAssimp, MissingAndEmptyFilesAreInputErrors) {
    TempDir dir;
    EXPECT_THROW(importScene(dir.path("absent.obj")), InputError);
    EXPECT_THROW(importScene(dir.write("empty.obj", "")), InputError);
    EXPECT_THROW(importScene(sharedModels() + "/obj"), InputError);  // a folder
}

TEST(ImportAssimp, OnlyPointsAndLinesIsNothingToConvert) {
    TempDir dir;
    EXPECT_THROW(importScene(dir.write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n")), InputError);
}

// A triangle with a repeated vertex is dropped and counted; the rest converts.
TEST(ImportAssimp, DegenerateFacesAreDroppedAndCounted) {
    TempDir dir;
    const ImportResult r = importScene(dir.write("d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 2\n"));
    EXPECT_EQ(test::modelTriangles(r.scene), 1u);
    EXPECT_EQ(r.report.droppedDegenerate, 1u);
}

}  // namespace
}  // namespace rt
