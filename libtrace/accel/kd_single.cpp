// The single-ray queries of the KD and BSP trees (SplitTree::intersect, occluded): front to back
// down the tree's 8-byte nodes, a leaf's primitives tested in blocks (geometry/leaf_block.h).
// Compiled three times (accel/simd_level.h), once per set of lanes: on AVX2 and AVX-512 a leaf's
// blocks are tested two at a time, and the compiler's code has three-operand instructions (no
// register copies) and, for AVX-512, 32 registers: with AVX2, 25 % fewer instructions per camera
// ray than SSE2's took before (docs/benchmarks.md). Each level's arithmetic is IEEE's, operation by
// operation (no fused multiply-add), so every copy gives the same bits. SplitTree::intersect and
// occluded choose a copy at run time (simd_dispatch.cpp); the packet traversal of a level hands its
// lone rays to that level's copy (kd_packet.cpp).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "accel/split_tree.h"

// Last, in a block of its own: the level's region starts in it (accel/simd_level.h).
#include "accel/leaf_tests.h"

namespace rt {

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
    // Per axis, whether the ray runs towards lower values (-0 counts, as its reciprocal is -inf):
    // then the upper child is the near one, the one a plane ahead of the origin has the origin in.
    const bool downward[3] = {std::signbit(ray.direction.x), std::signbit(ray.direction.y),
                              std::signbit(ray.direction.z)};
    struct Pending {
        std::uint32_t node;
        Real tMin, tMax;
    };
    Pending stack[kMaxTreeDepth];
    int size = 0;
    std::uint64_t steps = 0;            // in a register; added to the caller's counters once
    const PrimitiveView prims = view_;  // a local copy, kept in registers (see PrimitiveView)
    // A plane at a distance below tLow lies behind the part of the ray in the node, or behind the
    // origin, or through it (tPlane 0 or -0: the origin on the plane, the ray moving away from the
    // side it leaves): only the far child is left. With tMin 0 that is tPlane <= 0.
    Real tLow = std::max(tMin, std::numeric_limits<Real>::denorm_min());
    for (;;) {
        // Down to a leaf. On the way tMin stays and tLimit, which only a leaf lowers, too:
        // the early exit is tested once per leaf, after the next node is taken from the stack.
        SplitNode node = nodes_[index];
        while (!node.isLeaf()) {
            ++steps;
            const int axis = node.axis();
            const Real split = node.split();
            const Real tPlane = (split - origin[axis]) * inverse[axis];
            const std::uint32_t below = index + 1, above = node.aboveChild();
            const std::uint32_t nearChild = downward[axis] ? above : below;
            const std::uint32_t farChild = downward[axis] ? below : above;
            if (tPlane > tMax) {
                index = nearChild;
            } else if (tPlane < tLow) {
                index = farChild;
            } else if (!std::isnan(tPlane)) {
                stack[size++] = {farChild, tPlane, tMax};
                prefetchNode(farChild);
                index = nearChild;
                tMax = tPlane;
            } else {
                // The ray lies in the plane (0 * inf fails every test above): primitives on
                // either side may touch it, so both children get the whole interval. The origin
                // is on the plane, and belongs to the side the ray moves into (below for 0).
                const bool belowFirst = direction[axis] <= 0;
                stack[size++] = {belowFirst ? above : below, tMin, tMax};
                prefetchNode(stack[size - 1].node);
                index = belowFirst ? below : above;
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
        tLow = std::max(tMin, std::numeric_limits<Real>::denorm_min());
    }
    counters.traversalSteps += steps;
}

// Nearest hit: the leaves' loop of accel/leaf_tests.h.
template <SimdLevel level, TriangleTest test>
void SplitTree::searchNearest(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin, Real tMax,
                              Hit& nearest, RayCounters& counters) const {
    const RT_LEVEL_LANES::BlockTests<test> testBlocks(ray);
    const HitFilter* filter = filter_;
    std::uint64_t tests = 0;  // in a register; added to the caller's counters once
    traverse(
        ray, invDir, node, tMin, tMax, nearest.t,
        counters, [&](const PrimitiveView& prims, const LeafPrimitives& leaf) __attribute__((always_inline)) {
            RT_LEVEL_LANES::nearestInLeaf(testBlocks, prims, leaf, ray, filter, nearest, tests);
            return false;  // a nearer hit may still lie in a later node; traverse() knows when not
        });
    counters.intersectionTests += tests;
}

// Any hit before `rayTMax`, the whole shadow ray's end, in the subtree at `node`.
template <SimdLevel level, TriangleTest test>
bool SplitTree::searchBlocker(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin, Real tMax,
                              Real rayTMax, RayCounters& counters) const {
    const RT_LEVEL_LANES::BlockTests<test> testBlocks(ray);
    std::uint64_t tests = 0;
    bool found = false;
    const HitFilter* filter = filter_;
    traverse(
        ray, invDir, node, tMin, tMax, rayTMax,
        counters, [&](const PrimitiveView& prims, const LeafPrimitives& leaf) __attribute__((always_inline)) {
            return found = RT_LEVEL_LANES::blockerInLeaf(testBlocks, prims, leaf, ray, rayTMax, filter, tests);
        });
    counters.intersectionTests += tests;
    return found;
}

template void SplitTree::searchNearest<RT_LEVEL, TriangleTest::MollerTrumbore>(const Ray&, const Vec3&, std::uint32_t,
                                                                               Real, Real, Hit&, RayCounters&) const;
template void SplitTree::searchNearest<RT_LEVEL, TriangleTest::Watertight>(const Ray&, const Vec3&, std::uint32_t, Real,
                                                                           Real, Hit&, RayCounters&) const;
template bool SplitTree::searchBlocker<RT_LEVEL, TriangleTest::MollerTrumbore>(const Ray&, const Vec3&, std::uint32_t,
                                                                               Real, Real, Real, RayCounters&) const;
template bool SplitTree::searchBlocker<RT_LEVEL, TriangleTest::Watertight>(const Ray&, const Vec3&, std::uint32_t, Real,
                                                                           Real, Real, RayCounters&) const;

}  // namespace rt

RT_LEVEL_END
