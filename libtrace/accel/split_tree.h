// The structure the BSP and KD trees share (thesis 2.4, 2.5): a binary partition of
// space by axis-aligned planes whose leaves list the primitives they overlap. The two
// trees differ only in where their builders put the planes (bsp.cpp, kdtree.cpp);
// traversal, statistics and the node visitor live here, once.
//
// Layout, as in pbrt-v3's KdTreeAccel: 8-byte nodes in one array in pre-order, so the
// lower child of an inner node is the next node and only the upper child's index is
// stored; leaves point into one flat array of primitive indices.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <new>
#include <span>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "accel/leaf_store.h"
#include "accel/settings.h"
#include "accel/shape_stats.h"

namespace rt {

// One node in 8 bytes. The split position is a float even when Real is double: the
// builders round every plane to float before they sort primitives against it, so the
// tree is exact for the planes it stores.
class SplitNode {
public:
    static SplitNode leaf(std::uint32_t primitiveOffset, std::uint32_t primitiveCount) {
        return SplitNode(primitiveOffset, (primitiveCount << 2) | 3u);
    }
    static SplitNode inner(int axis, float split, std::uint32_t aboveChild) {
        return SplitNode(std::bit_cast<std::uint32_t>(split), (aboveChild << 2) | std::uint32_t(axis));
    }

    bool isLeaf() const { return (bits_ & 3u) == 3u; }
    int axis() const { return int(bits_ & 3u); }
    float split() const { return std::bit_cast<float>(word_); }
    std::uint32_t aboveChild() const { return bits_ >> 2; }  // the below child is this node + 1
    std::uint32_t primitiveOffset() const { return word_; }
    std::uint32_t primitiveCount() const { return bits_ >> 2; }

    // Moves a subtree built on its own to `nodeBase` and `primitiveBase` in a larger array.
    void relocate(std::uint32_t nodeBase, std::uint32_t primitiveBase) {
        if (isLeaf())
            word_ += primitiveBase;
        else
            bits_ += nodeBase << 2;
    }

private:
    SplitNode(std::uint32_t word, std::uint32_t bits) : word_(word), bits_(bits) {}
    std::uint32_t word_;  // split position (inner) or offset into the primitive indices (leaf)
    std::uint32_t bits_;  // axis 0-2 or 3 for a leaf, then the upper child or the primitive count
};
static_assert(sizeof(SplitNode) == 8);

// A tree (or subtree) as the builders produce it.
struct FlatTree {
    std::vector<SplitNode> nodes;  // pre-order
    std::vector<std::uint32_t> primitiveIndices;

    void addLeaf(std::span<const std::uint32_t> primitives);
    // Appends `subtree`, built separately, fixing its node and primitive offsets.
    void append(const FlatTree& subtree);
};

// The trees' SAH constants (accel/shape_stats.h) are KdSettings's, the one place they are set:
// both trees report with sahCosts(KdSettings).
inline SahCosts sahCosts(const KdSettings& kd) { return {kd.traversalCost, kd.intersectionCost}; }

class SplitTree final : public Accelerator {
public:
    // `bounds` is the root voxel; every plane in `tree` must lie inside it. The leaves' triangles
    // are tested with `triangles`.
    SplitTree(const Primitives& prims, const Aabb& bounds, FlatTree tree, std::string name, SahCosts costs,
              TriangleTest triangles = TriangleTest::MollerTrumbore);

    bool intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const override;
    bool occluded(const Ray& ray, Real tMax, RayCounters& counters) const override;
    // Wald's packet traversal (accel/kd_packet.cpp) on the lanes simdLevel() chooses (core/simd.h).
    void intersectPacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found,
                         RayCounters& counters) const override;
    // Its any-hit form, each ray stopping where occluded() stops (accel/kd_packet.cpp).
    void occludedPacket(const Ray* rays, int count, const Real* tMax, bool* blocked,
                        RayCounters& counters) const override;
    AccelStats stats() const override { return stats_; }
    void forEachNode(const std::function<void(const TreeNodeInfo&)>& visit) const override;

    void setBuildTime(double seconds, int threads) {
        stats_.buildSeconds = seconds;
        stats_.buildThreads = threads;
    }

private:
    void layOutLeaves(const FlatTree& tree);
    LeafPrimitives leafSizes(const FlatTree& tree, const SplitNode& node) const {
        return LeafStore::sizesOf(prims_, &tree.primitiveIndices[node.primitiveOffset()], node.primitiveCount());
    }
    // The packet traversals on one level's lanes with one triangle test: kd_packet.cpp, compiled
    // once per level.
    template <SimdLevel level, TriangleTest test>
    void tracePacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found, RayCounters& counters) const;
    template <SimdLevel level, TriangleTest test>
    void traceShadowPacket(const Ray* rays, int count, const Real* tMax, bool* blocked, RayCounters& counters) const;
    // Whether `count` rays may walk the tree as a packet (kd_packet.cpp checks that they are coherent).
    bool tracesTogether(int count) const { return count >= 2 && !nodes_.empty() && !bounds_.empty(); }
    // The part [tMin, tMax] of the ray inside the root voxel; false if it misses the voxel.
    bool enters(const Ray& ray, const Vec3& invDir, Real& tMin, Real& tMax) const {
        tMin = 0;
        return !nodes_.empty() && !bounds_.empty() && clipRay(bounds_, ray, invDir, tMin, tMax);
    }
    // The single-ray queries in the subtree at `node`, for the part [tMin, tMax] of the ray inside
    // it: from the root for intersect() and occluded(), from deeper for a ray a packet hands on alone.
    // invDir: reciprocal(ray.direction), found once per ray by the caller. On one level's lanes:
    // kd_single.cpp, compiled once per level and triangle test.
    template <SimdLevel level, TriangleTest test>
    void searchNearest(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin, Real tMax, Hit& nearest,
                       RayCounters& counters) const;
    template <SimdLevel level, TriangleTest test>
    bool searchBlocker(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin, Real tMax, Real rayTMax,
                       RayCounters& counters) const;
    template <typename LeafVisitor>
    void traverse(const Ray& ray, const Vec3& invDir, std::uint32_t index, Real tMin, Real tMax, const Real& tLimit,
                  RayCounters& counters, const LeafVisitor& visitLeaf) const;
    // The far child waits on the stack while the near one is searched: its node is fetched meanwhile.
    void prefetchNode(std::uint32_t index) const { __builtin_prefetch(&nodes_[index]); }
    // Called at a leaf for the node next on the stack (fetched when it was pushed): if that node is
    // a leaf, its record and first block are fetched while this leaf is tested, so that the two
    // leaves' cache misses overlap instead of following each other. No branch on the node, whose
    // load may still be on its way: an inner node fetches its own cache line again, which is there.
    void prefetchLeafOf(std::uint32_t index) const {
        const SplitNode node = nodes_[index];
        // As integers: an inner node's offset is its split's bits, no place in leaves_.
        const auto leafBytes = leaves_.address(node.primitiveOffset());
        const auto nodeBytes = std::uintptr_t(&nodes_[index]);
        const auto* at = reinterpret_cast<const char*>(node.isLeaf() ? leafBytes : nodeBytes);
        for (std::size_t line = 0; line < kLeafPrefetchBytes; line += 64) __builtin_prefetch(at + line);
        __builtin_prefetch(at + kLeafPrefetchBytes - 1);  // the last cache line, when the leaf starts inside one
    }
    AccelStats computeStats(std::string name, SahCosts costs) const;

    const Primitives& prims_;
    PrimitiveView view_;  // of prims_, which must not change while the tree is used
    Aabb bounds_;
    // As the builder made them, except that a non-empty leaf's primitiveOffset() is where its
    // LeafPrimitives lies in leaves_, in 16-byte units.
    std::vector<SplitNode> nodes_;
    LeafStore leaves_;  // sized, then written in parallel (layOutLeaves)
    const LeafPrimitives& leafAt(std::uint32_t unit) const { return leaves_.at(unit); }
    AccelStats stats_;
};

}  // namespace rt
