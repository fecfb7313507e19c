// Traversal of hand-built trees: the corner cases the property tests rarely meet.
#include "accel/split_tree.h"

#include "test_util.h"

using namespace rt;

namespace {

// Root split at z = 0; below: sphere 0; above: sphere 1, touching the plane at the origin.
struct TwoSpheres {
    Primitives prims;
    std::unique_ptr<SplitTree> tree;

    TwoSpheres() {
        prims.add<Sphere>({{0, 0, Real(-1.5)}, Real(0.5)}, 0);
        prims.add<Sphere>({{0, 0, Real(0.5)}, Real(0.5)}, 0);
        FlatTree flat;
        flat.nodes.push_back(SplitNode::inner(2, 0.0f, 2));
        flat.addLeaf(std::vector<std::uint32_t>{0});
        flat.addLeaf(std::vector<std::uint32_t>{1});
        tree = std::make_unique<SplitTree>(prims, Aabb{{-2, -2, -2}, {2, 2, 2}}, flat, "test", SahCosts{1.0, 1.5});
    }
};

}  // namespace

TEST(SplitNode, PacksIntoEightBytes) {
    const SplitNode inner = SplitNode::inner(1, 0.25f, 12345);
    EXPECT_FALSE(inner.isLeaf());
    EXPECT_EQ(inner.axis(), 1);
    EXPECT_EQ(inner.split(), 0.25f);
    EXPECT_EQ(inner.aboveChild(), 12345u);
    const SplitNode leaf = SplitNode::leaf(77, 1u << 29);
    EXPECT_TRUE(leaf.isLeaf());
    EXPECT_EQ(leaf.primitiveOffset(), 77u);
    EXPECT_EQ(leaf.primitiveCount(), 1u << 29);
}

TEST(SplitTree, RayInTheSplitPlaneSeesBothSides) {
    const TwoSpheres s;
    RayCounters counters;
    Hit hit;
    // Along the plane z = 0, grazing sphere 1 at the origin: 0 * inf = NaN for this axis,
    // and the ray "starts" below (it does not move up), yet the upper side must be seen.
    ASSERT_TRUE(s.tree->intersect({{-5, 0, 0}, {1, 0, 0}}, kInfinity, hit, counters));
    EXPECT_EQ(hit.prim, 1u);
    EXPECT_NEAR(hit.t, 5, kTol);
    EXPECT_TRUE(s.tree->occluded({{-5, 0, 0}, {1, 0, 0}}, 6, counters));
}

TEST(SplitTree, FrontToBackStopsAtTheFirstNodeWithAHit) {
    const TwoSpheres s;
    RayCounters down, up;
    Hit hit;
    ASSERT_TRUE(s.tree->intersect({{0, 0, 5}, {0, 0, -1}}, kInfinity, hit, down));
    EXPECT_EQ(hit.prim, 1u);
    EXPECT_NEAR(hit.t, 4, kTol);
    EXPECT_EQ(down.intersectionTests, 1u);  // the lower leaf was never opened
    ASSERT_TRUE(s.tree->intersect({{0, 0, -5}, {0, 0, 1}}, kInfinity, hit, up));
    EXPECT_EQ(hit.prim, 0u);
    EXPECT_NEAR(hit.t, 3, kTol);
    EXPECT_EQ(up.intersectionTests, 1u);
    EXPECT_EQ(up.traversalSteps, 2u);
}

TEST(SplitTree, RayStartingOnThePlaneGoesToTheSideItMovesInto) {
    const TwoSpheres s;
    RayCounters counters;
    Hit hit;
    ASSERT_TRUE(s.tree->intersect({{0, 0, 0}, {0, 0, 1}}, kInfinity, hit, counters));
    EXPECT_EQ(hit.prim, 1u);  // from its surface, through the inside, to the far side
    EXPECT_NEAR(hit.t, 1, kTol);
    EXPECT_EQ(counters.intersectionTests, 1u);
    EXPECT_FALSE(s.tree->occluded({{0, 0, Real(0.5)}, {0, 0, 1}}, Real(0.4), counters));
}

TEST(SplitTree, StatsAndVisitorDescribeTheTree) {
    const TwoSpheres s;
    const AccelStats st = s.tree->stats();
    EXPECT_EQ(st.nodes, 3u);
    EXPECT_EQ(st.leaves, 2u);
    EXPECT_EQ(st.primitiveReferences, 2u);
    // nodes, then each leaf's record and a block of spheres holding its sphere
    EXPECT_EQ(st.memoryBytes, 3 * 8u + 2 * (sizeof(LeafPrimitives) + sizeof(SphereBlock)));
    EXPECT_DOUBLE_EQ(st.bytesPerPrimitive(), double(st.memoryBytes) / 2);
    EXPECT_EQ(st.maxDepth, 1u);
    // Root 1.0 * C_T; each half has area 2*(16 + 2*4*2) = 64 of 96: 2 * 1.5 * 1 * 2/3.
    EXPECT_NEAR(st.sahCost, 1.0 + 2.0, 1e-9);
    std::vector<TreeNodeInfo> nodes;
    s.tree->forEachNode([&](const TreeNodeInfo& n) { nodes.push_back(n); });
    ASSERT_EQ(nodes.size(), 3u);
    ASSERT_TRUE(nodes[0].plane);
    EXPECT_EQ(nodes[0].plane->axis, 2);
    EXPECT_FALSE(nodes[1].plane);  // a leaf
    EXPECT_EQ(nodes[1].id, 1u);
    EXPECT_EQ(nodes[1].bounds.hi.z, 0);  // the lower child first
    EXPECT_EQ(nodes[2].bounds.lo.z, 0);
    EXPECT_EQ(nodes[2].depth, 1u);
}

// One leaf of six triangles (blocks of kSimdWidth, two or four: the last one then half empty) across the z axis at
// z = 6, 5, ..., 1, listed farthest first so that every lane's hit is nearer than the one
// before, and a sphere: the leaf's nearest hit must be the scalar test's, to the bit.
TEST(SplitTree, LeafBlocksFindTheNearestTriangleAsTheScalarTestDoes) {
    Primitives prims;
    for (int i = 0; i < 6; ++i) {
        const Real z = Real(6 - i);
        prims.add<Triangle>({{-1, -1, z}, {Real(1.5), Real(-0.5), z + Real(0.1)}, {Real(-0.25), 1, z}}, 0);
    }
    prims.add<Sphere>({{0, 0, Real(0.5)}, Real(0.25)}, 0);
    FlatTree flat;
    flat.addLeaf(std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5, 6});
    const SplitTree tree(prims, Aabb{{-2, -2, -2}, {8, 8, 8}}, flat, "test", SahCosts{1.0, 1.5});
    RayCounters counters;
    const Ray ray{{Real(0.1), Real(0.2), 0}, normalize(Vec3{Real(0.01), Real(-0.02), 1})};

    Hit hit;
    ASSERT_TRUE(tree.intersect(ray, kInfinity, hit, counters));
    EXPECT_EQ(hit.prim, 6u);  // the sphere, nearer than every triangle
    Real t, u, v;
    const Ray fromAbove{ray.origin + ray.direction * Real(0.9), ray.direction};  // past the sphere
    ASSERT_TRUE(intersectTriangle(prims.all<Triangle>()[5], fromAbove, kInfinity, t, u, v));
    ASSERT_TRUE(tree.intersect(fromAbove, kInfinity, hit, counters));
    EXPECT_EQ(hit.prim, 5u);
    EXPECT_EQ(hit.t, t);
    EXPECT_EQ(hit.u, u);
    EXPECT_EQ(hit.v, v);
    EXPECT_EQ(counters.intersectionTests, 2 * 7u);

    EXPECT_TRUE(tree.occluded(fromAbove, t * Real(1.01), counters));
    EXPECT_FALSE(tree.occluded(fromAbove, t * Real(0.99), counters));
}
