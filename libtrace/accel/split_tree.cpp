#include "accel/split_tree.h"

#include <algorithm>
#include <cstring>
#include <optional>
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

SplitTree::SplitTree(const Primitives& prims, const Aabb& bounds, FlatTree tree, std::string name, SahCosts costs)
    : prims_(prims), view_(prims.view()), bounds_(bounds), nodes_(std::move(tree.nodes)) {
    layOutLeaves(tree);
    stats_ = computeStats(std::move(name), costs);
}

// Lays each non-empty leaf out in leafData_: its record, its triangles in blocks in leaf order,
// its spheres likewise, then its other ids. Each kind keeps its order among itself, and the kinds
// are tested in that order; the order decides only between hits at exactly the same distance. A large tree is
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
    leafData_.resize(starts.back());
#pragma omp parallel for schedule(static) if (count > 1)
    for (std::int64_t c = 0; c < count; ++c) {
        std::size_t at = starts[std::size_t(c)];
        for (std::size_t n = chunks.begin(std::size_t(c)); n < chunks.end(std::size_t(c)); ++n) {
            SplitNode& node = nodes_[n];
            if (!node.isLeaf() || node.primitiveCount() == 0) continue;
            const LeafPrimitives sizes = leafSizes(tree, node);
            layOutLeaf(&tree.primitiveIndices[node.primitiveOffset()], sizes, at);
            node = SplitNode::leaf(std::uint32_t(at), node.primitiveCount());
            at += sizes.units();
        }
    }
}

// The record of the leaf `node` as the builder made it: how many of its primitives are triangles
// and spheres.
LeafPrimitives SplitTree::leafSizes(const FlatTree& tree, const SplitNode& node) const {
    const std::uint32_t* ids = &tree.primitiveIndices[node.primitiveOffset()];
    LeafPrimitives sizes;
    for (std::uint32_t i = 0; i < node.primitiveCount(); ++i) {
        sizes.triangles += prims_.indexIn<Triangle>(ids[i]) ? 1 : 0;
        sizes.spheres += prims_.indexIn<Sphere>(ids[i]) ? 1 : 0;
    }
    sizes.others = node.primitiveCount() - sizes.triangles - sizes.spheres;
    return sizes;
}

namespace {

// Copies the blocks of Kind one by one to `out`, each full block or the last as it is filled:
// set(block, lane, primitive, id) fills a lane.
template <class Block, class Kind>
class BlockWriter {
public:
    BlockWriter(std::byte* out, std::uint32_t count) : out_(out), count_(count) {}
    void add(const Kind& primitive, std::uint32_t id) {
        if (written_ % kSimdWidth == 0) block_ = Block();
        block_.set(int(written_ % kSimdWidth), primitive, id);
        ++written_;
        if (written_ % kSimdWidth == 0 || written_ == count_) {
            std::memcpy(out_, &block_, sizeof(block_));
            out_ += sizeof(block_);
        }
    }

private:
    std::byte* out_;
    std::uint32_t count_, written_ = 0;
    Block block_;
};

}  // namespace

// Writes the leaf of the primitives `ids` (its record `sizes`) to leafData_ from unit `at` on.
// (Copying the bytes of these trivially copyable types creates them there.)
void SplitTree::layOutLeaf(const std::uint32_t* ids, const LeafPrimitives& sizes, std::size_t at) {
    std::byte* out = leafData_[at].bytes;
    std::memcpy(out, &sizes, sizeof(sizes));
    std::byte* const triangleBlocks = out + sizeof(LeafPrimitives);
    std::byte* const sphereBlocks = triangleBlocks + sizes.blockCount() * sizeof(TriangleBlock);
    std::byte* others = sphereBlocks + sizes.sphereBlockCount() * sizeof(SphereBlock);
    BlockWriter<TriangleBlock, Triangle> triangles(triangleBlocks, sizes.triangles);
    BlockWriter<SphereBlock, Sphere> spheres(sphereBlocks, sizes.spheres);
    for (std::uint32_t i = 0; i < sizes.triangles + sizes.spheres + sizes.others; ++i) {
        if (const std::optional<std::uint32_t> triangle = prims_.indexIn<Triangle>(ids[i])) {
            triangles.add(prims_.all<Triangle>()[*triangle], ids[i]);
        } else if (const std::optional<std::uint32_t> sphere = prims_.indexIn<Sphere>(ids[i])) {
            spheres.add(prims_.all<Sphere>()[*sphere], ids[i]);
        } else {
            std::memcpy(others, &ids[i], sizeof(std::uint32_t));
            others += sizeof(std::uint32_t);
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
// probability proportional to its surface area, relative to the root's.
AccelStats SplitTree::computeStats(std::string name, SahCosts costs) const {
    AccelStats s;
    s.name = std::move(name);
    s.primitives = prims_.size();
    s.memoryBytes = nodes_.size() * sizeof(SplitNode) + leafData_.size() * sizeof(LeafUnit);
    const double rootArea = bounds_.surfaceArea();
    double leafDepthSum = 0;
    std::uint64_t nonEmptyLeaves = 0;
    forEachNode([&](const TreeNodeInfo& n) {
        ++s.nodes;
        s.maxDepth = std::max(s.maxDepth, n.depth);
        const double probability = rootArea > 0 ? n.bounds.surfaceArea() / rootArea : 1.0;
        if (!n.leaf) {
            s.sahCost += costs.traversal * probability;
            return;
        }
        ++s.leaves;
        leafDepthSum += n.depth;
        s.primitiveReferences += n.primitives;
        if (n.primitives == 0)
            ++s.emptyLeaves;
        else
            ++nonEmptyLeaves;
        s.sahCost += costs.intersection * n.primitives * probability;
    });
    s.averageLeafDepth = s.leaves ? leafDepthSum / double(s.leaves) : 0;
    s.averagePrimitivesPerLeaf = nonEmptyLeaves ? double(s.primitiveReferences) / double(nonEmptyLeaves) : 0;
    return s;
}

}  // namespace rt
