// The BSP tree's planes, stopping rules and exact primitive sorting (thesis 2.4.1).
#include "accel/bsp.h"

#include <vector>

#include "accel/split_tree.h"
#include "scene/generate.h"
#include "test_util.h"

using namespace rt;

namespace {

// Scene bounds [0, 4] x [0, 2] x [0, 1], set by two small spheres in opposite corners.
Primitives longBox() {
    Primitives prims;
    prims.add<Sphere>({{Real(0.1), Real(0.1), Real(0.1)}, Real(0.1)}, 0);
    prims.add<Sphere>({{Real(3.9), Real(1.9), Real(0.9)}, Real(0.1)}, 0);
    return prims;
}

}  // namespace

TEST(BspTree, SplitsTheLongestAxisInTheMiddle) {
    BspSettings settings;
    settings.minPrimitives = 0;
    settings.maxDepth = 3;
    const auto tree = buildBspTree(longBox(), settings);
    const auto nodes = nodesOf(*tree);
    ASSERT_GE(nodes.size(), 3u);
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(nodes[i].plane) << "node " << i;
    EXPECT_EQ(nodes[0].plane->axis, 0);  // x is 4 long
    EXPECT_FLOAT_EQ(float(nodes[0].plane->position), 2.0f);
    // The lower half [0, 2] x [0, 2] x [0, 1]: x and y tie and ties go to x; then y is longest.
    EXPECT_EQ(nodes[1].plane->axis, 0);
    EXPECT_EQ(nodes[1].depth, 1u);
    EXPECT_FLOAT_EQ(float(nodes[1].plane->position), 1.0f);
    EXPECT_EQ(nodes[2].plane->axis, 1);
    EXPECT_FLOAT_EQ(float(nodes[2].plane->position), 1.0f);
}

TEST(BspTree, RoundRobinCyclesTheAxes) {
    BspSettings settings;
    settings.minPrimitives = 0;
    settings.maxDepth = 3;
    settings.roundRobin = true;
    const auto tree = buildBspTree(longBox(), settings);
    for (const TreeNodeInfo& n : nodesOf(*tree)) {
        if (!n.leaf) {
            ASSERT_TRUE(n.plane) << "node " << n.id;
            EXPECT_EQ(n.plane->axis, int(n.depth % 3)) << "node " << n.id;
        }
    }
}

TEST(BspTree, StopsAtMinimumPrimitivesAndMaximumDepth) {
    const Primitives prims = generateScene({2000, 0, Placement::Uniform, 3}).primitives;
    BspSettings shallow;
    shallow.maxDepth = 5;
    const AccelStats s = buildBspTree(prims, shallow)->stats();
    EXPECT_EQ(s.maxDepth, 5u);
    EXPECT_GT(s.nodes, 31u);
    BspSettings fewPerLeaf;
    fewPerLeaf.minPrimitives = 3000;  // the root already holds fewer
    EXPECT_EQ(buildBspTree(prims, fewPerLeaf)->stats().nodes, 1u);
    // A leaf above the depth limit holds at most minPrimitives, unless its plane would have
    // cut every one of its primitives (then splitting gains nothing): a rare case.
    BspSettings defaults;
    int leaves = 0, crowded = 0;
    for (const TreeNodeInfo& n : nodesOf(*buildBspTree(prims, defaults))) {
        leaves += n.leaf;
        crowded += n.leaf && n.depth < std::uint32_t(defaults.maxDepth) && n.primitives > 4;
    }
    EXPECT_LT(crowded * 20, leaves);
}

TEST(BspTree, SortsPrimitivesByExactOverlapNotBoundingBoxes) {
    // Scene [0, 2] x [0, 2] x [0, 1]. The triangle x + y >= 2.5 has bounds [0.5, 2]^2, which
    // reach into the voxel [0, 1]^2 of depth 2; the triangle itself does not.
    Primitives prims;
    prims.add<Sphere>({{Real(0.05), Real(0.05), Real(0.05)}, Real(0.05)}, 0);
    prims.add<Sphere>({{Real(1.95), Real(1.95), Real(0.95)}, Real(0.05)}, 0);
    prims.add<Triangle>({{Real(0.5), 2, Real(0.5)}, {2, Real(0.5), Real(0.5)}, {2, 2, Real(0.5)}}, 0);
    BspSettings settings;
    settings.minPrimitives = 0;
    settings.maxDepth = 2;
    const auto tree = buildBspTree(prims, settings);
    bool seen = false;
    for (const TreeNodeInfo& n : nodesOf(*tree)) {
        if (n.leaf && n.bounds.hi.x == 1 && n.bounds.hi.y == 1) {
            EXPECT_EQ(n.primitives, 1u);  // the corner sphere only
            seen = true;
        }
    }
    EXPECT_TRUE(seen);
    EXPECT_EQ(tree->stats().primitiveReferences, 2u + 3u);  // the triangle is in three of the four leaves
}

TEST(BspTree, StatisticsAddUp) {
    const Primitives prims = generateScene({3000, 500, Placement::Clustered, 4}).primitives;
    const auto tree = buildBspTree(prims, BspSettings{});
    const AccelStats s = tree->stats();
    std::uint64_t references = 0, leaves = 0, empty = 0;
    for (const TreeNodeInfo& n : nodesOf(*tree)) {
        if (!n.leaf) continue;
        ++leaves;
        references += n.primitives;
        empty += n.primitives == 0;
    }
    EXPECT_EQ(s.name, "bsp");
    EXPECT_EQ(s.nodes, 2 * s.leaves - 1);
    EXPECT_EQ(s.leaves, leaves);
    EXPECT_EQ(s.emptyLeaves, empty);
    EXPECT_EQ(s.primitiveReferences, references);
    EXPECT_GE(s.primitiveReferences, prims.size());
    // Nodes, a record per non-empty leaf, the leaves' triangles in blocks of kSimdWidth (a block
    // partly empty at most once per leaf) and the other primitives' ids (padded to 16 bytes a leaf).
    const std::uint64_t nonEmpty = s.leaves - s.emptyLeaves;
    EXPECT_GE(s.memoryBytes, 8 * s.nodes + 4 * s.primitiveReferences);
    EXPECT_LE(s.memoryBytes, 8 * s.nodes + (sizeof(LeafPrimitives) + 12) * nonEmpty +
                                 sizeof(TriangleBlock) * (s.primitiveReferences / kSimdWidth + nonEmpty) +
                                 4 * s.primitiveReferences);
    EXPECT_GT(s.sahCost, 0);
}
