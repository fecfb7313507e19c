#include "accel/split_tree.h"

#include <algorithm>
#include <utility>

#include "accel/build_chunks.h"

namespace rt {

void FlatTree::addLeaf(std::span<const std::uint32_t> primitives) {
    nodes.push_back(SplitNode::leaf(std::uint32_t(primitiveIndices.size()), std::uint32_t(primitives.size())));
    primitiveIndices.insert(primitiveIndices.end(), primitives.begin(), primitives.end());
}

void FlatTree::append(const FlatTree& subtree) {
    const auto nodeBase = std::uint32_t(nodes.size());
    const auto primitiveBase = std::uint32_t(primitiveIndices.size());
    for (SplitNode node : subtree.nodes) {
        node.relocate(nodeBase, primitiveBase);
        nodes.push_back(node);
    }
    primitiveIndices.insert(primitiveIndices.end(), subtree.primitiveIndices.begin(), subtree.primitiveIndices.end());
}

SplitTree::SplitTree(const Primitives& prims, const Aabb& bounds, FlatTree tree, std::string name, SahCosts costs,
                     TriangleTest triangles)
    : prims_(prims), view_(prims.view()), bounds_(bounds), nodes_(std::move(tree.nodes)), leaves_(triangles) {
    layOutLeaves(tree);
    stats_ = computeStats(std::move(name), costs);
}

// Lays each non-empty leaf out in leaves_ (accel/leaf_store.h). A large tree is
// laid out in chunks of nodes on all threads (a tenth of the tree scene's build): each chunk
// counts its leaves' units, and fills its part from where the chunks before it end.
void SplitTree::layOutLeaves(const FlatTree& tree) {
    const Chunks chunks(nodes_.size(), kTaskPrimitives);
    const auto count = std::int64_t(chunks.count());
    std::vector<std::size_t> starts(chunks.count() + 1);  // starts[c + 1]: chunk c's units, then summed
#pragma omp parallel for schedule(static) if (count > 1)
    for (std::int64_t c = 0; c < count; ++c) {
        for (std::size_t n = chunks.begin(std::size_t(c)); n < chunks.end(std::size_t(c)); ++n)
            if (nodes_[n].isLeaf() && nodes_[n].primitiveCount() != 0)
                starts[std::size_t(c) + 1] += leafSizes(tree, nodes_[n]).units();
    }
    for (std::size_t c = 1; c < starts.size(); ++c) starts[c] += starts[c - 1];
    leaves_.resize(starts.back());
#pragma omp parallel for schedule(static) if (count > 1)
    for (std::int64_t c = 0; c < count; ++c) {
        std::size_t at = starts[std::size_t(c)];
        for (std::size_t n = chunks.begin(std::size_t(c)); n < chunks.end(std::size_t(c)); ++n) {
            SplitNode& node = nodes_[n];
            if (!node.isLeaf() || node.primitiveCount() == 0) continue;
            const LeafPrimitives sizes = leafSizes(tree, node);
            leaves_.write(prims_, &tree.primitiveIndices[node.primitiveOffset()], sizes, at);
            node = SplitNode::leaf(std::uint32_t(at), node.primitiveCount());
            at += sizes.units();
        }
    }
}

void SplitTree::forEachNode(const std::function<void(const TreeNodeInfo&)>& visit) const {
    if (nodes_.empty()) return;
    struct Pending {
        std::uint32_t node, depth;
        Aabb bounds;
    };
    std::vector<Pending> stack{{0, 0, bounds_}};
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        const SplitNode node = nodes_[p.node];
        TreeNodeInfo info;
        info.id = p.node;  // nodes are stored in pre-order
        info.depth = p.depth;
        info.bounds = p.bounds;
        info.leaf = node.isLeaf();
        if (node.isLeaf()) {
            info.primitives = node.primitiveCount();
        } else {
            info.plane = SplitPlane{node.axis(), node.split()};
            Aabb below = p.bounds, above = p.bounds;
            below.hi[node.axis()] = node.split();
            above.lo[node.axis()] = node.split();
            stack.push_back({node.aboveChild(), p.depth + 1, above});
            stack.push_back({p.node + 1, p.depth + 1, below});  // popped first: lower child first
        }
        visit(info);
    }
}

// The tree's expected cost per ray by the SAH (thesis 2.5.1): each node is entered with
// probability proportional to its voxel's surface area, relative to the root's.
AccelStats SplitTree::computeStats(std::string name, SahCosts costs) const {
    AccelStats s;
    s.name = std::move(name);
    s.primitives = prims_.size();
    s.memoryBytes = nodes_.size() * sizeof(SplitNode) + leaves_.bytes();
    addShapeStatistics(*this, bounds_.surfaceArea(), costs, s);
    return s;
}

}  // namespace rt
