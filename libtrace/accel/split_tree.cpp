#include "accel/split_tree.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

#include "accel/build_chunks.h"

namespace rt {

void FlatTree::addLeaf(const std::vector<std::uint32_t>& primitives) {
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
// then its other ids. The triangles keep their order among themselves and are tested before the
// other kinds; the order decides only between hits at exactly the same distance. A large tree is
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

// The record of the leaf `node` as the builder made it: how many of its primitives are triangles.
LeafPrimitives SplitTree::leafSizes(const FlatTree& tree, const SplitNode& node) const {
    const std::uint32_t* ids = &tree.primitiveIndices[node.primitiveOffset()];
    std::uint32_t triangles = 0;
    for (std::uint32_t i = 0; i < node.primitiveCount(); ++i) triangles += prims_.indexIn<Triangle>(ids[i]) ? 1 : 0;
    return {triangles, node.primitiveCount() - triangles};
}

// Writes the leaf of the primitives `ids` (its record `sizes`) to leafData_ from unit `at` on.
// (Copying the bytes of these trivially copyable types creates them there.)
void SplitTree::layOutLeaf(const std::uint32_t* ids, const LeafPrimitives& sizes, std::size_t at) {
    std::byte* out = leafData_[at].bytes;
    std::memcpy(out, &sizes, sizeof(sizes));
    auto* blocks = out + sizeof(LeafPrimitives);
    auto* others = blocks + sizes.blockCount() * sizeof(TriangleBlock);
    TriangleBlock block;
    std::uint32_t triangles = 0;
    for (std::uint32_t i = 0; i < sizes.triangles + sizes.others; ++i) {
        const std::optional<std::uint32_t> triangle = prims_.indexIn<Triangle>(ids[i]);
        if (!triangle) {
            std::memcpy(others, &ids[i], sizeof(std::uint32_t));
            others += sizeof(std::uint32_t);
            continue;
        }
        if (triangles % kSimdWidth == 0) block = TriangleBlock();
        block.set(int(triangles % kSimdWidth), prims_.all<Triangle>()[*triangle], ids[i]);
        ++triangles;
        if (triangles % kSimdWidth == 0 || triangles == sizes.triangles) {
            std::memcpy(blocks, &block, sizeof(block));
            blocks += sizeof(block);
        }
    }
}

// Front-to-back traversal with an explicit stack (Havran's TA_B, thesis [7]; pbrt-v3's
// KdTreeAccel::Intersect). Each stack entry is a far child still to visit and the part
// [tMin, tMax] of the ray inside it. Entries lower in the stack lie farther along the
// ray, so once the nearest hit so far (`tLimit`) lies before the current node, nothing
// left can be nearer and the search stops.
// The descent keeps its branches: the same choices made without them (masks and selects) ran at
// half the speed, each node's load then waiting for the last one's arithmetic instead of being
// issued on a prediction (docs/benchmarks.md, branch `descent`). What it adds is prefetching: a
// pushed far child's node, and at a leaf the next leaf on the stack, are fetched ahead of use.
// It starts at `index` with the part [tMin, tMax] of the ray inside that node, and ends when the
// subtree is searched: from the root for a whole ray, from a deeper node for a ray that a packet
// hands on alone (kd_packet.cpp), which then visits what its own traversal would have visited there.
template <typename LeafVisitor>
void SplitTree::traverse(const Ray& ray, const Vec3& invDir, std::uint32_t index, Real tMin, Real tMax,
                         const Real& tLimit, RayCounters& counters, const LeafVisitor& visitLeaf) const {
    // Indexed by the split axis in the loop: arrays, not Vec3's branching operator[].
    const Real origin[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const Real direction[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    const Real inverse[3] = {invDir.x, invDir.y, invDir.z};
    struct Pending {
        std::uint32_t node;
        Real tMin, tMax;
    };
    Pending stack[kMaxTreeDepth];
    int size = 0;
    std::uint64_t steps = 0;            // in a register; added to the caller's counters once
    const PrimitiveView prims = view_;  // a local copy, kept in registers (see PrimitiveView)
    for (;;) {
        // Down to a leaf. On the way tMin stays and tLimit, which only a leaf lowers, too:
        // the early exit is tested once per leaf, after the next node is taken from the stack.
        SplitNode node = nodes_[index];
        while (!node.isLeaf()) {
            ++steps;
            const int axis = node.axis();
            const Real split = node.split();
            const Real tPlane = (split - origin[axis]) * inverse[axis];
            // The child holding the origin comes first; an origin on the plane belongs to
            // the side the ray moves into.
            const bool belowFirst = origin[axis] < split || (origin[axis] == split && direction[axis] <= 0);
            const std::uint32_t first = belowFirst ? index + 1 : node.aboveChild();
            const std::uint32_t second = belowFirst ? node.aboveChild() : index + 1;
            if (tPlane > tMax || tPlane <= 0) {
                index = first;
            } else if (tPlane < tMin) {
                index = second;
            } else if (!std::isnan(tPlane)) {
                stack[size++] = {second, tPlane, tMax};
                prefetchNode(second);
                index = first;
                tMax = tPlane;
            } else {
                // The ray lies in the plane (0 * inf fails every test above): primitives on
                // either side may touch it, so both children get the whole interval.
                stack[size++] = {second, tMin, tMax};
                prefetchNode(second);
                index = first;
            }
            node = nodes_[index];
        }
        ++steps;
        if (size != 0) prefetchLeafOf(stack[size - 1].node);
        if (node.primitiveCount() != 0 && visitLeaf(prims, leafAt(node.primitiveOffset()))) break;
        if (size == 0) break;
        --size;
        index = stack[size].node;
        tMin = stack[size].tMin;
        tMax = stack[size].tMax;
        if (tLimit < tMin) break;
    }
    counters.traversalSteps += steps;
}

// The far child waits on the stack while the near one is searched: its node is fetched meanwhile.
void SplitTree::prefetchNode(std::uint32_t index) const { __builtin_prefetch(&nodes_[index]); }

// Called at a leaf for the node next on the stack (fetched when it was pushed): if that node is a
// leaf, its record and first block are fetched while this leaf is tested, so that the two leaves'
// cache misses overlap instead of following each other. No branch on the node, whose load may
// still be on its way: an inner node fetches its own cache line again, which is there already.
void SplitTree::prefetchLeafOf(std::uint32_t index) const {
    const SplitNode node = nodes_[index];
    // As integers: an inner node's offset is its split's bits, no place in leafData_.
    const auto leafBytes = std::uintptr_t(leafData_.data()) + std::uintptr_t(node.primitiveOffset()) * sizeof(LeafUnit);
    const auto nodeBytes = std::uintptr_t(&nodes_[index]);
    const auto* at = reinterpret_cast<const char*>(node.isLeaf() ? leafBytes : nodeBytes);
    for (std::size_t line = 0; line < kLeafPrefetchBytes; line += 64) __builtin_prefetch(at + line);
    __builtin_prefetch(at + kLeafPrefetchBytes - 1);  // the last cache line, when the leaf starts inside one
}

// The part [tMin, tMax] of the ray inside the root voxel; false if it misses the voxel.
bool SplitTree::enters(const Ray& ray, const Vec3& invDir, Real& tMin, Real& tMax) const {
    tMin = 0;
    return !nodes_.empty() && !bounds_.empty() && clipRay(bounds_, ray, invDir, tMin, tMax);
}

bool SplitTree::intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const {
    Hit nearest;
    nearest.t = tMax;
    const Vec3 invDir = reciprocal(ray.direction);
    Real tMin = 0, tEnd = tMax;
    if (enters(ray, invDir, tMin, tEnd)) searchNearest(ray, invDir, 0, tMin, tEnd, nearest, counters);
    // A hit only ever lowers nearest.t: no flag to keep in the leaf loop.
    if (!(nearest.t < tMax)) return false;
    hit = nearest;
    return true;
}

// Nearest hit: each block's hits are taken in lane order, as the scalar loop took the
// triangles, each only if nearer than the nearest so far (a lane before it may have come nearer)
// and, in a scene with a hit filter (cut-outs, single-sided materials), only if it accepts it.
void SplitTree::searchNearest(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin, Real tMax,
                              Hit& nearest, RayCounters& counters) const {
    const RayLanes lanes(ray);
    const HitFilter* filter = filter_;
    std::uint64_t tests = 0;  // in a register; added to the caller's counters once
    traverse(ray, invDir, node, tMin, tMax, nearest.t, counters,
             [&](const PrimitiveView& prims, const LeafPrimitives& leaf) {
                 tests += leaf.triangles + leaf.others;
                 const TriangleBlock* blocks = leaf.blocks();
                 for (std::uint32_t b = 0; b < leaf.blockCount(); ++b) {
                     const BlockHits hits = intersectBlock(blocks[b], lanes, nearest.t);
                     for (unsigned bits = hits.lanes; bits != 0; bits &= bits - 1) {
                         const int lane = std::countr_zero(bits);
                         if (!(hits.t[lane] < nearest.t)) continue;
                         const Hit candidate{hits.t[lane], blocks[b].id[lane], hits.u[lane], hits.v[lane]};
                         if (filter && !filter->accepts(ray, candidate)) continue;
                         nearest = candidate;
                     }
                 }
                 const std::uint32_t* otherIds = leaf.otherIds();
                 for (std::uint32_t i = 0; i < leaf.others; ++i) {
                     if (filter)
                         intersectFiltered(prims, otherIds[i], ray, *filter, nearest);
                     else
                         prims.intersect(otherIds[i], ray, nearest.t, nearest);
                 }
                 return false;  // a nearer hit may still lie in a later node; traverse() knows when not
             });
    counters.intersectionTests += tests;
}

bool SplitTree::occluded(const Ray& ray, Real tMax, RayCounters& counters) const {
    const Vec3 invDir = reciprocal(ray.direction);
    Real tMin = 0, tEnd = tMax;
    return enters(ray, invDir, tMin, tEnd) && searchBlocker(ray, invDir, 0, tMin, tEnd, tMax, counters);
}

// Any hit before `rayTMax`, the whole shadow ray's end, in the subtree at `node`.
bool SplitTree::searchBlocker(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin, Real tMax,
                              Real rayTMax, RayCounters& counters) const {
    const RayLanes lanes(ray);
    std::uint64_t tests = 0;
    bool found = false;
    const HitFilter* filter = filter_;
    // whether a block's hits count: any of them without a filter, else one the filter accepts
    const auto counts = [&](const TriangleBlock& block, const BlockHits& hits) {
        if (!filter) return hits.lanes != 0;
        for (unsigned bits = hits.lanes; bits != 0; bits &= bits - 1) {
            const int lane = std::countr_zero(bits);
            if (filter->accepts(ray, {hits.t[lane], block.id[lane], hits.u[lane], hits.v[lane]})) return true;
        }
        return false;
    };
    traverse(ray, invDir, node, tMin, tMax, rayTMax, counters,
             [&](const PrimitiveView& prims, const LeafPrimitives& leaf) {
                 for (std::uint32_t b = 0; b < leaf.blockCount(); ++b) {
                     tests += std::min<std::uint32_t>(kSimdWidth, leaf.triangles - b * kSimdWidth);
                     const TriangleBlock& block = leaf.blocks()[b];
                     if (counts(block, intersectBlock(block, lanes, rayTMax))) return found = true;
                 }
                 const std::uint32_t* otherIds = leaf.otherIds();
                 for (std::uint32_t i = 0; i < leaf.others; ++i) {
                     ++tests;
                     const bool hits = filter ? occludesFiltered(prims, otherIds[i], ray, rayTMax, *filter)
                                              : prims.intersectsAny(otherIds[i], ray, rayTMax);
                     if (hits) return found = true;
                 }
                 return false;
             });
    counters.intersectionTests += tests;
    return found;
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
