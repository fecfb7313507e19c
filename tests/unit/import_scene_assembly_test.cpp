// The scaffolding the importers share (import/scene_assembly.h): a mesh converted once however
// often it is placed, degenerate triangles counted per model and per placement, materials made
// once and only when an instance uses them, names unique.
#include <gtest/gtest.h>

#include <utility>

#include "io/scene_assembly.h"

namespace rt {
namespace {

// One triangle with an area and one without.
ConvertedMesh oneKeptOneDropped(SceneAssembly<int, int>& assembly, const std::string& name) {
    ModelBuilder model = assembly.newModel(name, "mesh");
    model.addTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
    model.addTriangle({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
    return assembly.addModel(std::move(model));
}

TEST(ImportSceneAssembly, AMeshIsConvertedOnceAndItsDropsCountPerPlacement) {
    ImportResult out;
    SceneAssembly<int, int> assembly(out);
    int conversions = 0;
    for (int placement = 0; placement < 3; ++placement) {
        const ConvertedMesh mesh = assembly.mesh(7, [&] {
            ++conversions;
            return oneKeptOneDropped(assembly, "wheel");
        });
        assembly.place(
            mesh, [] { return 0u; }, Transform());
    }
    EXPECT_EQ(conversions, 1);
    ASSERT_EQ(out.scene.models.size(), 1u);
    EXPECT_EQ(out.scene.models[0].triangleCount(), 1u);
    EXPECT_EQ(out.scene.instances.size(), 3u);
    EXPECT_EQ(out.report.droppedDegenerate, 1u);
    EXPECT_EQ(out.report.droppedDegenerateInScene, 3u);
}

TEST(ImportSceneAssembly, AModelWithoutTrianglesIsNeitherAddedNorPlaced) {
    ImportResult out;
    SceneAssembly<int, int> assembly(out);
    ModelBuilder model = assembly.newModel("flat", "mesh");
    model.addTriangle({0, 0, 0}, {0, 0, 0}, {0, 1, 0});
    const ConvertedMesh mesh = assembly.addModel(std::move(model));
    EXPECT_FALSE(mesh.model);
    bool materialMade = false;
    assembly.place(
        mesh, [&] { return materialMade = true, 0u; }, Transform());
    EXPECT_TRUE(out.scene.models.empty());
    EXPECT_TRUE(out.scene.instances.empty());
    EXPECT_FALSE(materialMade);
    EXPECT_EQ(out.report.droppedDegenerateInScene, 1u);
}

TEST(ImportSceneAssembly, MaterialsAreMadeOnceWithUniqueSafeNames) {
    ImportResult out;
    SceneAssembly<int, int> assembly(out);
    int made = 0;
    const auto steel = [&] {
        ++made;
        Material m;
        m.name = "steel plate";
        return m;
    };
    EXPECT_EQ(assembly.material(4, "material4", steel), 0u);
    EXPECT_EQ(assembly.material(4, "material4", steel), 0u);
    EXPECT_EQ(assembly.material(5, "material5", steel), 1u);
    EXPECT_EQ(assembly.material(6, "material6", [] { return Material{}; }), 2u);
    EXPECT_EQ(made, 2);
    ASSERT_EQ(out.scene.materials.size(), 3u);
    EXPECT_EQ(out.scene.materials[0].name, "steel_plate");
    EXPECT_EQ(out.scene.materials[1].name, "steel_plate_2");
    EXPECT_EQ(out.scene.materials[2].name, "material6");
}

TEST(ImportSceneAssembly, ModelNamesAreUniqueAndDropsOutsideModelsCountOnce) {
    ImportResult out;
    SceneAssembly<int, int> assembly(out);
    EXPECT_EQ(*oneKeptOneDropped(assembly, "part").model, 0u);
    EXPECT_EQ(*oneKeptOneDropped(assembly, "part").model, 1u);
    EXPECT_EQ(out.scene.models[1].name, "part_2");
    assembly.dropDegenerate(4);
    EXPECT_EQ(out.report.droppedDegenerate, 6u);
    EXPECT_EQ(out.report.droppedDegenerateInScene, 4u);  // nothing placed yet
    assembly.countFaceWithoutArea(1);
    assembly.countFaceWithoutArea(2);
    assembly.countFaceWithoutArea(3);
    EXPECT_EQ(out.report.droppedPoints, 1u);
    EXPECT_EQ(out.report.droppedLines, 1u);
}

}  // namespace
}  // namespace rt
