// Import through Assimp (libtrace/import/assimp_import.*): the shared 3DS models against the
// Assimp figures of MANIFEST.md, cameras, format detection and broken files. OBJ has its own
// importer (import_obj_test.cpp).
#include <gtest/gtest.h>

#include "core/error.h"
#include "import_test_util.h"
#include "io/import.h"
#include "io/scene_defaults.h"
#include "test_util.h"

namespace rt {
namespace {

using test::sharedModels;
using test::TempDir;

TEST(ImportAssimp, TriangleCountsMatchTheManifest) {
    SKIP_WITHOUT_SHARED_MODELS();
    const std::size_t files = test::expectManifestTriangleCounts({"3ds"}, [](const ImportResult& r) {
        EXPECT_EQ(r.scene.models.size(), r.scene.instances.size());  // 3DS files do not instance
    });
    EXPECT_EQ(files, 9u);
}

// A 3DS camera lands where its node puts it, looking at its target; no camera is generated.
TEST(ImportAssimp, ThreeDsCameraIsUsed) {
    SKIP_WITHOUT_SHARED_MODELS();
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

// A 3DS material's transparency (83 % opaque) lets the rest through, straight on (no index);
// the file's opaque materials stay opaque.
TEST(ImportAssimp, ThreeDsTransparencyLetsLightThrough) {
    SKIP_WITHOUT_SHARED_MODELS();
    const ImportResult r = importScene(sharedModels() + "/3ds/cubes_with_alpha/cubes_with_alpha.3DS");
    int transparent = 0;
    for (const Material& m : r.scene.materials) {
        if (m.name != "Transparent") {
            EXPECT_FALSE(m.transmission.passesLight()) << m.name;
            continue;
        }
        ++transparent;
        EXPECT_NEAR(m.transmission.weight, 0.17f, 1e-5);
        EXPECT_TRUE(m.transmission.thin);
    }
    EXPECT_EQ(transparent, 1);
}

// Garbage whose keywords look like OBJ text, under a name without extension.
TEST(ImportAssimp, ContentGuessesAreOnlyTrustedForBinaryFormats) {
    SKIP_WITHOUT_SHARED_MODELS();
    EXPECT_THROW(
        importScene(sharedModels() + "/bad/assimp-fuzz/clusterfuzz-testcase-minimized-assimp_fuzzer-4751812606885888"),
        InputError);
    const ImportResult r = importScene(sharedModels() + "/3ds/testFormatDetection/testFormatDetection");
    EXPECT_EQ(r.report.format, "Discreet 3DS Importer");
}

// Assimp's glTF importers are removed: a glTF JSON under another name is unknown, not parsed.
TEST(ImportAssimp, AssimpNeverReadsGltf) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    std::ifstream in(sharedModels() + "/gltf/Box/Box.gltf");
    const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_THROW(importScene(dir.write("box.json", json)), InputError);
}

TEST(ImportAssimp, MissingAndEmptyFilesAreInputErrors) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    EXPECT_THROW(importScene(dir.path("absent.ply")), InputError);
    EXPECT_THROW(importScene(dir.write("empty.ply", "")), InputError);
    EXPECT_THROW(importScene(sharedModels() + "/3ds"), InputError);  // a folder
}

// --up-axis says how the file stands, whatever the importer does: Assimp's 3DS reader already
// turns 3D Studio's Z-up to Y-up, so a triangle standing along the file's +Z stands along rt's
// +Y by default and with --up-axis z (before: on its nose, along -Z), and keeps the file's
// axes with --up-axis y.
TEST(ImportAssimp, UpAxisDescribesTheFileNotTheImporter) {
    TempDir dir;
    const std::string path = test::ThreeDsFixture::write(
        dir, test::ThreeDsFixture::file({test::ThreeDsFixture::mesh("tall", {0, 0, 0, 1, 0, 0, 0, 0, 10})}));
    for (const std::optional<UpAxis> up : {std::optional<UpAxis>(), std::optional<UpAxis>(UpAxis::Z)}) {
        ImportOptions o;
        o.upAxis = up;
        const Aabb b = sceneBounds(importScene(path, o).scene);
        EXPECT_NEAR(b.lo.y, 0, 1e-5);
        EXPECT_NEAR(b.hi.y, 10, 1e-5) << "the file's +Z is rt's up";
        EXPECT_NEAR(b.hi.z - b.lo.z, 0, 1e-5);
    }
    ImportOptions o;
    o.upAxis = UpAxis::Y;
    const Aabb b = sceneBounds(importScene(path, o).scene);
    EXPECT_NEAR(b.hi.z, 10, 1e-5) << "a file said to be Y-up keeps its axes";
    EXPECT_NEAR(b.hi.y - b.lo.y, 0, 1e-5);
}

// A 3DS omni light, which Assimp gives with a zero direction, is a point light where the file
// puts it (issue 36: such a scene was refused by every tool).
TEST(ImportAssimp, ThreeDsOmniLightIsAPointLight) {
    TempDir dir;
    using test::ThreeDsFixture;
    const std::string path = ThreeDsFixture::write(
        dir, ThreeDsFixture::file({ThreeDsFixture::mesh("tri", {0, 0, 0, 1, 0, 0, 0, 1, 0}),
                                   ThreeDsFixture::omniLight("Omni01", {1, 2, 3}, {0.5f, 0.25f, 1})}));
    const ImportResult r = importScene(path);
    EXPECT_EQ(r.report.lightsInFile, 1u);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    const Light& omni = r.scene.lights[0];
    EXPECT_EQ(omni.type, Light::Type::Point);
    EXPECT_NEAR(omni.position.x, 1, 1e-5);  // the file's Z-up axes turned to rt's Y-up: (x, z, -y)
    EXPECT_NEAR(omni.position.y, 3, 1e-5);
    EXPECT_NEAR(omni.position.z, -2, 1e-5);
    EXPECT_NEAR(omni.color.b, 1, 1e-6);
    EXPECT_NEAR(omni.color.r, 0.5, 1e-6);
    EXPECT_FALSE(r.report.lightGenerated);
}

}  // namespace
}  // namespace rt
