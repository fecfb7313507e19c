// Triangles kept only with an area in float, and model bounds (import/mesh_data.*).
#include <gtest/gtest.h>

#include "import/mesh_data.h"

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

TEST(ImportMeshData, BoundsOfAModel) {
    Model m;
    appendTriangle(m, {-1, 0, 2}, {1, 0, 0}, {0, 3, 0});
    const Aabb b = modelBounds(m);
    EXPECT_EQ(b.lo, Vec3(-1, 0, 0));
    EXPECT_EQ(b.hi, Vec3(1, 3, 2));
    EXPECT_TRUE(modelBounds(Model()).empty());
}

}  // namespace
}  // namespace rt
