// The BVH as the traversal reads it (accel/bvh.h builds it): nodes of eight children, each child's
// box stored component by component (Embree's BVH8 layout) so that one node's eight slab tests are
// one or two registers' work; a child is an inner node or a leaf of accel/leaf_store.h.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "accel/accelerator.h"
#include "accel/leaf_store.h"
#include "accel/settings.h"
#include "core/simd.h"

namespace rt {

inline constexpr int kBvhWidth = 8;
// The deepest the builder makes a BVH (it switches to median splits on the way, accel/bvh_build.cpp):
// the traversal's stack holds the far children of every level.
inline constexpr int kMaxBvhDepth = 96;

// A child of a node: an inner node's index, or a leaf's first 16-byte unit in the LeafStore.
class BvhChild {
public:
    static BvhChild inner(std::uint32_t node) { return BvhChild(node); }
    static BvhChild leaf(std::uint32_t unit) { return BvhChild(unit | kLeafBit); }

    BvhChild() = default;  // uninitialized, so that the traversal's stack costs nothing to make
    bool isLeaf() const { return (bits_ & kLeafBit) != 0; }
    std::uint32_t index() const { return bits_ & ~kLeafBit; }  // the node, or the leaf's unit

private:
    static constexpr std::uint32_t kLeafBit = 1u << 31;
    explicit BvhChild(std::uint32_t bits) : bits_(bits) {}
    std::uint32_t bits_;
};

// The largest magnitude of a point's coordinates, and of a box's (0 for an empty box, +inf for an
// unbounded one): the scale of their rounding, for the builder's padding and the traversal's slack.
inline Real largestMagnitude(const Vec3& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }
inline Real largestMagnitude(const Aabb& box) {
    return box.empty() ? 0 : std::max(largestMagnitude(box.lo), largestMagnitude(box.hi));
}

// How far along a ray a child's box is taken to reach beyond its computed slab interval
// (accel/bvh_traversal.cpp says why): kBvhSlackUlps units in the last place of the larger of the
// ray origin's and the scene's largest magnitudes, `sceneMagnitude`.
inline constexpr Real kBvhSlackUlps = 64;
inline Real slabSlack(const Ray& ray, Real sceneMagnitude) {
    return kBvhSlackUlps * std::numeric_limits<Real>::epsilon() * (largestMagnitude(ray.origin) + sceneMagnitude);
}

// An unused slot has an empty box (lo = +inf, hi = -inf), which no ray enters.
struct alignas(64) BvhNode {
    Real lo[3][kBvhWidth];
    Real hi[3][kBvhWidth];
    BvhChild child[kBvhWidth];
    std::uint32_t children = 0;  // used slots, the first ones

    BvhNode();
    void add(const Aabb& box, BvhChild c);
    Aabb box(int slot) const;
    Aabb bounds() const;  // of its children
};

class Bvh final : public Accelerator {
public:
    // `nodes` in pre-order, the root first; `leaves` holds every leaf a node names. The build took
    // `buildSeconds` on `buildThreads` threads.
    Bvh(const Primitives& prims, std::vector<BvhNode> nodes, LeafStore leaves, const BvhSettings& settings,
        double buildSeconds, int buildThreads);

    bool intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const override;
    bool occluded(const Ray& ray, Real tMax, RayCounters& counters) const override;
    // Packets of coherent rays walk the nodes together (accel/bvh_packet.cpp).
    void intersectPacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found,
                         RayCounters& counters) const override;
    void occludedPacket(const Ray* rays, int count, const Real* tMax, bool* blocked,
                        RayCounters& counters) const override;
    AccelStats stats() const override { return stats_; }
    // Inner nodes and leaves in pre-order, the children of a node in slot order.
    void forEachNode(const std::function<void(const TreeNodeInfo&)>& visit) const override;

private:
    // The queries on one level's lanes with one triangle test, below `start` (the root, or the node
    // where a packet left a ray alone): accel/bvh_traversal.cpp, compiled once per level. With
    // `noteTies`, searchNearest sets `*tied` where a leaf meets a hit as near as the nearest
    // (nearestInLeaf, accel/leaf_tests.h).
    template <SimdLevel level, TriangleTest test, bool noteTies = false>
    void searchNearest(const Ray& ray, BvhChild start, Hit& nearest, RayCounters& counters, bool* tied = nullptr) const;
    template <SimdLevel level, TriangleTest test>
    bool searchBlocker(const Ray& ray, BvhChild start, Real tMax, RayCounters& counters) const;
    // The packet queries: accel/bvh_packet.cpp, compiled once per level.
    template <SimdLevel level, TriangleTest test>
    void tracePacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found, RayCounters& counters) const;
    template <SimdLevel level, TriangleTest test>
    void traceShadowPacket(const Ray* rays, int count, const Real* tMax, bool* blocked, RayCounters& counters) const;
    AccelStats computeStats(const BvhSettings& settings) const;

    const Primitives& prims_;
    PrimitiveView view_;   // of prims_, which must not change while the BVH is used
    Real sceneMagnitude_;  // largestMagnitude of the scene, finite (0 if not): scales each ray's slack
    std::vector<BvhNode> nodes_;
    LeafStore leaves_;
    AccelStats stats_;
};

}  // namespace rt
