// Tangent frames for normal maps (libtrace/geometry/tangents.*, Scene::flatten): generated
// where a model has none, a file's (glTF's TANGENT, RAW's vtan) kept as given and placed with
// the instance.
#include "geometry/tangents.h"

#include "scene/scene.h"
#include "test_util.h"

using namespace rt;

namespace {

// One triangle in z = 0 with texture coordinates along x and y, its material normal-mapped,
// placed by `xf`; `tangent` (x y z w at each corner) given as the file's when not empty.
Scene normalMappedTriangle(const std::vector<float>& tangent, const Transform& xf) {
    Scene s;
    s.textures.push_back({.name = "normals"});
    Material m{.name = "bumpy"};
    m.normalMap.texture = 0;
    s.materials.push_back(m);
    Model tri;
    tri.triangleVertices = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    tri.vertexUvs = {0, 0, 1, 0, 0, 1};
    for (int c = 0; c < 3 && !tangent.empty(); ++c)
        tri.vertexTangents.insert(tri.vertexTangents.end(), tangent.begin(), tangent.end());
    s.models.push_back(tri);
    s.instances.push_back({0, 0, xf});
    s.flatten();
    return s;
}

std::array<float, 4> firstCorner(const Scene& s) {
    const CornerTangents* t = s.primitives.triangleShading().tangents.find(0);
    EXPECT_NE(t, nullptr);
    return t ? std::array<float, 4>{t->values[0], t->values[1], t->values[2], t->values[3]} : std::array<float, 4>{};
}

}  // namespace

TEST(Tangents, GeneratedAlongIncreasingU) {
    const std::array<float, 4> t = firstCorner(normalMappedTriangle({}, Transform()));
    EXPECT_NEAR(t[0], 1, 1e-6);
    EXPECT_NEAR(t[1], 0, 1e-6);
    EXPECT_EQ(std::abs(t[3]), 1);
}

// A file's tangent wins over the generated one, even one the texture coordinates would not give
// (glTF lets the file choose); a mirroring instance turns its handedness.
TEST(Tangents, AFilesTangentsAreKeptAndPlacedWithTheInstance) {
    const std::vector<float> diagonal = {0.6f, 0.8f, 0, -1};
    const std::array<float, 4> kept = firstCorner(normalMappedTriangle(diagonal, Transform()));
    EXPECT_NEAR(kept[0], 0.6, 1e-6);
    EXPECT_NEAR(kept[1], 0.8, 1e-6);
    EXPECT_EQ(kept[3], -1);
    const std::array<float, 4> mirrored = firstCorner(normalMappedTriangle(diagonal, Transform::scale({-2, 1, 1})));
    const Real len = std::hypot(1.2, 0.8);
    EXPECT_NEAR(mirrored[0], -1.2 / len, 1e-6);
    EXPECT_NEAR(mirrored[1], 0.8 / len, 1e-6);
    EXPECT_EQ(mirrored[3], 1);
}
