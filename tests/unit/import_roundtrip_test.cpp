// Imported scenes written with saveSceneXml and read back with loadSceneXml (what rt-convert
// and rt-render do) give the same world-space triangles, camera and lights; one RAW file
// per model; and loadScene reads model files directly.
#include <gtest/gtest.h>

#include <filesystem>

#include "import_test_util.h"
#include "io/import.h"
#include "io/load_scene.h"
#include "io/xml_loader.h"
#include "io/xml_writer.h"
#include "test_util.h"

namespace rt {
namespace {

using test::sharedModels;
using test::TempDir;

std::size_t rawFilesIn(const std::string& folder) {
    std::size_t n = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) n += entry.path().extension() == ".raw";
    return n;
}

void expectSameTriangles(const Primitives& a, const Primitives& b) {
    ASSERT_EQ(a.count<Triangle>(), b.count<Triangle>());
    for (std::uint32_t i = 0; i < a.count<Triangle>(); ++i) {
        expectNear(a.all<Triangle>()[i].p0, b.all<Triangle>()[i].p0, Real(1e-5));
        expectNear(a.all<Triangle>()[i].p2, b.all<Triangle>()[i].p2, Real(1e-5));
        EXPECT_EQ(a.material(i), b.material(i));
    }
}

class ImportRoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(ImportRoundTrip, WrittenAndReadBackIsTheSameScene) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    ImportResult imported = importScene(sharedModels() + "/" + GetParam());
    saveSceneXml(imported.scene, dir.path("scene.xml"));
    EXPECT_EQ(rawFilesIn(dir.path("scene")), imported.scene.models.size()) << "one RAW file per distinct mesh";

    const Scene loaded = loadSceneXml(dir.path("scene.xml"));
    imported.scene.flatten();
    expectSameTriangles(imported.scene.primitives, loaded.primitives);
    EXPECT_EQ(loaded.instances.size(), imported.scene.instances.size());
    expectNear(loaded.camera.origin, imported.scene.camera.origin, Real(1e-5));
    expectNear(loaded.camera.destination, imported.scene.camera.destination, Real(1e-5));
    ASSERT_TRUE(loaded.camera.fovDegrees);
    EXPECT_NEAR(*loaded.camera.fovDegrees, *imported.scene.camera.fovDegrees, 1e-4);
    ASSERT_EQ(loaded.lights.size(), imported.scene.lights.size());
    for (std::size_t i = 0; i < loaded.lights.size(); ++i)
        expectNear(loaded.lights[i].position, imported.scene.lights[i].position, Real(1e-4));
}

INSTANTIATE_TEST_SUITE_P(Models, ImportRoundTrip,
                         ::testing::Values("gltf/SharedMesh/02_shared_mesh.gltf",
                                           "glb/2CylinderEngine/2CylinderEngine.glb",
                                           "gltf/PointLightCamera-issue261/issue-261.gltf",
                                           "obj/CornellBox-Original/CornellBox-Original.obj", "3ds/jeep1/jeep1.3ds"));

TEST(ImportLoadScene, ReadsModelFilesDirectly) {
    SKIP_WITHOUT_SHARED_MODELS();
    const Scene scene = loadScene(sharedModels() + "/glb/2CylinderEngine/2CylinderEngine.glb");
    EXPECT_EQ(scene.primitives.count<Triangle>(), 121496u - scene.droppedDegenerate);
    EXPECT_FALSE(scene.warnings.empty());  // the generated light is reported
}

TEST(ImportLoadScene, ReadsXmlThroughTheSceneLoader) {
    SKIP_WITHOUT_SHARED_MODELS();
    TempDir dir;
    saveSceneXml(importScene(sharedModels() + "/gltf/Box/Box.gltf").scene, dir.path("box.xml"));
    EXPECT_EQ(loadScene(dir.path("box.xml")).primitives.count<Triangle>(), 12u);
}

}  // namespace
}  // namespace rt
