// The shared recursion of the tree builders (libtrace/accel/tree_builder.h): subtrees built
// as OpenMP tasks come together in a fixed order, and an exception in any task (a
// std::bad_alloc on a scene too large for memory) reaches the caller instead of ending the
// process.
#include "accel/tree_builder.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <new>
#include <numeric>

namespace rt {
namespace {

struct Node {
    std::vector<std::uint32_t> primitives;
    int depth = 0;
};

// Halves every node down to `leafDepth`; throws std::bad_alloc at the node of depth
// `failDepth` whose first primitive is `failAt` (never, by default).
struct Halver {
    int leafDepth;
    int failDepth = -1;
    std::uint32_t failAt = 0;

    std::optional<Partition<Node>> operator()(const Node& node) const {
        if (node.depth == failDepth && node.primitives.front() == failAt) throw std::bad_alloc();
        if (node.depth == leafDepth) return std::nullopt;
        const auto middle = node.primitives.begin() + std::ptrdiff_t(node.primitives.size() / 2);
        Partition<Node> parts{0, float(node.depth), {}, {}};
        parts.below = {{node.primitives.begin(), middle}, node.depth + 1};
        parts.above = {{middle, node.primitives.end()}, node.depth + 1};
        return parts;
    }
};

Node root(std::uint32_t n) {
    Node node;
    node.primitives.resize(n);
    std::iota(node.primitives.begin(), node.primitives.end(), 0u);
    return node;
}

// 4 * kTaskPrimitives primitives: the two top levels are built as tasks.
constexpr std::uint32_t kPrimitives = 4 * kTaskPrimitives;

TEST(TreeBuilder, TasksGiveTheSameTreeAsOneThread) {
    omp_set_num_threads(1);
    const FlatTree one = buildFlatTree(root(kPrimitives), Halver{5});
    omp_set_num_threads(2);
    const FlatTree two = buildFlatTree(root(kPrimitives), Halver{5});
    ASSERT_EQ(one.nodes.size(), 63u);  // a full binary tree of depth 5
    ASSERT_EQ(two.nodes.size(), 63u);
    for (std::size_t i = 0; i < one.nodes.size(); ++i) {
        EXPECT_EQ(one.nodes[i].isLeaf(), two.nodes[i].isLeaf());
        if (!one.nodes[i].isLeaf()) {
            EXPECT_EQ(one.nodes[i].aboveChild(), two.nodes[i].aboveChild());
        }
    }
    EXPECT_EQ(one.primitiveIndices, two.primitiveIndices);
}

TEST(TreeBuilder, AnExceptionInATaskReachesTheCaller) {
    omp_set_num_threads(2);
    // Depth 1, above: a task's subtree; depth 4, inside it: a serial part below a task.
    for (const auto& [depth, at] : {std::pair{1, kPrimitives / 2}, std::pair{4, kPrimitives / 2 + kPrimitives / 8}}) {
        Halver failing{6, depth, at};
        EXPECT_THROW(buildFlatTree(root(kPrimitives), failing), std::bad_alloc) << "depth " << depth;
    }
    EXPECT_THROW(buildFlatTree(root(kPrimitives), Halver{6, 0, 0}), std::bad_alloc);  // the root itself
}

}  // namespace
}  // namespace rt
