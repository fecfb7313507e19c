// Triangles kept only with an area in float, and model bounds (import/mesh_data.*).
#include <gtest/gtest.h>

#include <limits>

#include "io/mesh_data.h"
#include "scene_test_files.h"

namespace rt {
namespace {

TEST(ImportMeshData, TrianglesWithoutAreaAreDropped) {
    Model m;
    EXPECT_TRUE(appendTriangle(m, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    EXPECT_FALSE(appendTriangle(m, {0, 0, 0}, {1, 1, 1}, {2, 2, 2}));         // collinear
    EXPECT_FALSE(appendTriangle(m, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}));         // repeated vertex
    EXPECT_TRUE(appendTriangle(m, {0, 0, 0}, {1e-3f, 0, 0}, {0, 1e-3f, 0}));  // small is fine
    EXPECT_EQ(m.triangleCount(), 2u);
    EXPECT_EQ(m.triangleVertices[3], 1.0f);
}

// A triangle faces away when its corners, counter-clockwise, give a normal against the sum of
// its vertex normals; flat triangles (zero normals) and models without normals are not counted.
TEST(ImportMeshData, WindingAgainstVertexNormals) {
    Model m;
    const float up[3] = {0, 0, 1}, down[3] = {0, 0, -1}, tilted[3] = {0.9f, 0, -0.1f}, none[3] = {0, 0, 0};
    // Counter-clockwise seen from +z: the geometric normal is +z.
    const auto add = [&m](const float* a, const float* b, const float* c) {
        ASSERT_TRUE(appendTriangleWithData(m, {{0, 0, 0}, a}, {{1, 0, 0}, b}, {{0, 1, 0}, c}));
    };
    EXPECT_EQ(windingAgainstNormals(m).withNormals, 0u);
    add(down, down, down);
    add(up, up, up);
    add(none, none, none);
    WindingAgainstNormals w = windingAgainstNormals(m);
    EXPECT_EQ(w.facingAway, 1u);
    EXPECT_EQ(w.withNormals, 2u);
    EXPECT_FALSE(w.mostlyFacingAway()) << "half is not most";
    add(up, down, tilted);  // the sum (0.9, 0, -0.1) points below the triangle
    w = windingAgainstNormals(m);
    EXPECT_EQ(w.facingAway, 2u);
    EXPECT_TRUE(w.mostlyFacingAway());
}

// Opacity below 1 lets the rest through and fades the surface's own light; an index above 1
// makes a refracting solid, else a thin sheet; opacity 1 or not finite changes nothing.
TEST(ImportMeshData, OpacityBelowOneLetsLightThrough) {
    Material veil;
    applyOpacity(veil, 0.25f, 1);
    EXPECT_FLOAT_EQ(veil.transmission.weight, 0.75f);
    EXPECT_TRUE(veil.transmission.thin);
    EXPECT_EQ(veil.transmission.ior, 1.0f);
    EXPECT_FLOAT_EQ(veil.phong.diffuse, Material{}.phong.diffuse * 0.25f);
    EXPECT_FLOAT_EQ(veil.phong.ambient, Material{}.phong.ambient * 0.25f);
    Material solid;
    applyOpacity(solid, 0.5f, 1.5f);
    EXPECT_FALSE(solid.transmission.thin);
    EXPECT_EQ(solid.transmission.ior, 1.5f);
    for (const float opacity : {1.0f, 2.0f, std::numeric_limits<float>::quiet_NaN()}) {
        Material same;
        applyOpacity(same, opacity, 1.5f);
        EXPECT_FALSE(same.transmission.passesLight()) << opacity;
        EXPECT_EQ(same.phong.diffuse, Material{}.phong.diffuse);
    }
}

TEST(ImportMeshData, BoundsOfAModel) {
    Model m;
    appendTriangle(m, {-1, 0, 2}, {1, 0, 0}, {0, 3, 0});
    const Aabb b = modelBounds(m);
    EXPECT_EQ(b.lo, Vec3(-1, 0, 0));
    EXPECT_EQ(b.hi, Vec3(1, 3, 2));
    EXPECT_TRUE(modelBounds(Model()).empty());
}

// Windows paths and other cases than the disk's find the file, as Windows and macOS tools do;
// a path that finds nothing, or two files that differ only in case, stay as written.
TEST(ImportMeshData, TexturesAreFoundThroughBackslashesAndOtherCase) {
    const TempDir dir;
    const std::filesystem::path folder = dir.path("model");
    dir.write("model/maps/wood.jpg", "x");
    dir.write("model/Same.png", "a");
    dir.write("model/same.PNG", "b");
    EXPECT_EQ(locateBeside(folder, "maps/wood.jpg"), folder / "maps/wood.jpg");
    EXPECT_EQ(locateBeside(folder, ".\\maps\\wood.jpg"), folder / "maps/wood.jpg");
    EXPECT_EQ(locateBeside(folder, "MAPS/WOOD.JPG"), folder / "maps/wood.jpg");
    EXPECT_EQ(locateBeside(folder, "Maps\\Wood.Jpg"), folder / "maps/wood.jpg");
    EXPECT_EQ(locateBeside(folder, "maps/oak.jpg"), folder / "maps/oak.jpg");
    EXPECT_EQ(locateBeside(folder, "same.png"), folder / "same.png");
    const Texture t = textureBeside((folder / "model.obj").string(), ".\\maps\\WOOD.jpg");
    EXPECT_EQ(t.path, (folder / "maps/wood.jpg").string());
    EXPECT_EQ(t.name, "wood");
}

}  // namespace
}  // namespace rt
