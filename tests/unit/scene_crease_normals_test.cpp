#include "scene/crease_normals.h"

#include "test_util.h"

using namespace rt;

namespace {

Vec3 normalAt(const Model& m, std::size_t triangle, int corner) {
    const float* n = &m.vertexNormals[9 * triangle + 3 * corner];
    return {n[0], n[1], n[2]};
}

// Two triangles sharing the edge (0,0,0)-(0,1,0), folded by `degrees` along it: the first in
// the plane z = 0, facing +z; the second turned about the y axis.
Model hinge(double degrees) {
    const float c = float(std::cos(degrees * kPi / 180)), s = float(std::sin(degrees * kPi / 180));
    Model m;
    m.triangleVertices = {0, 0, 0, 0, 1, 0, -1, 0, 0,   // facing +z
                          0, 0, 0, c, 0, s, 0,  1, 0};  // facing (-s, 0, c)
    return m;
}

}  // namespace

TEST(CreaseNormals, FacesBentLessThanTheCreaseAngleAreSmoothed) {
    Model m = hinge(20);
    addCreaseNormals(m, 30);
    ASSERT_EQ(m.vertexNormals.size(), 18u);
    // On the shared edge both faces meet: the normal lies halfway between them.
    const Real half = 10 * kPi / 180;
    expectNear(normalAt(m, 0, 0), {-std::sin(half), 0, std::cos(half)}, 1e-6);
    expectNear(normalAt(m, 1, 0), normalAt(m, 0, 0), 1e-6);
    expectNear(normalAt(m, 0, 1), normalAt(m, 1, 2), 1e-6);
    // The corners that are no one else's keep their face's normal.
    expectNear(normalAt(m, 0, 2), {0, 0, 1}, 1e-6);
}

TEST(CreaseNormals, EdgesSharperThanTheCreaseAngleStaySharp) {
    Model m = hinge(40);
    addCreaseNormals(m, 30);
    expectNear(normalAt(m, 0, 0), {0, 0, 1}, 1e-6);
    const Real a = 40 * kPi / 180;
    expectNear(normalAt(m, 1, 0), {-std::sin(a), 0, std::cos(a)}, 1e-6);
}

TEST(CreaseNormals, AngleWeightsMakeACubeCornerTheDiagonal) {
    // The corner (1,1,1) of a cube: three faces at right angles, each with one triangle there
    // (its right angle) and one that does not reach it; a crease angle over 90 degrees smooths
    // them, each face counting by its angle at the corner.
    Model m;
    m.triangleVertices = {1, 1, 1, 0, 1, 1, 1, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0, 1,   // z = 1
                          1, 1, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 0, 1, 0, 0, 1, 1,   // y = 1
                          1, 1, 1, 1, 0, 1, 1, 1, 0, 1, 0, 1, 1, 0, 0, 1, 1, 0};  // x = 1
    addCreaseNormals(m, 100);
    const Real d = 1 / std::sqrt(Real(3));
    for (std::size_t t : {0u, 2u, 4u}) expectNear(normalAt(m, t, 0), {d, d, d}, 1e-6);
    // At 30 degrees the cube keeps its faces.
    Model sharp = m;
    sharp.vertexNormals.clear();
    addCreaseNormals(sharp, kDefaultCreaseDegrees);
    expectNear(normalAt(sharp, 0, 0), {0, 0, 1}, 1e-6);
    expectNear(normalAt(sharp, 4, 0), {1, 0, 0}, 1e-6);
}

TEST(CreaseNormals, GivenNormalsAreKept) {
    Model m = hinge(10);
    m.vertexNormals.assign(18, 0);
    addCreaseNormals(m);
    EXPECT_EQ(m.vertexNormals, std::vector<float>(18, 0));
}
