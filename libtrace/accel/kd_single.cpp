// The single-ray queries of the KD and BSP trees (SplitTree::intersect, occluded): front to back
// down the tree's 8-byte nodes, a leaf's triangles tested in blocks (geometry/triangle_block.h).
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

// Last, in a block of its own (clang-format sorts a block): the level's region starts here.
#include "accel/simd_level.h"

// AVX2 and AVX-512 test a leaf's blocks two at a time, in one register twice SSE2's width (four
// doubles or eight floats; AVX-512 takes AVX2's register, compiled for its own level): one test's
// instructions for two blocks' triangles, each lane computing what it computes in a block alone.
#define RT_BLOCK_PAIRS (RT_LEVEL_AVX2 || RT_LEVEL_AVX512)

#if RT_BLOCK_PAIRS
namespace rt::RT_LEVEL_NAMESPACE {

namespace {

struct PairLanes {
    using Type = simd_avx2::RealLanes;
    static Type all(Real x) { return simd_avx2::broadcast(x); }
};
constexpr int kPairLanes = 2 * kSimdWidth;
static_assert(kPairLanes == simd_avx2::kLanes);
using PairHits = LaneHits<kPairLanes>;
// The lanes of a pair's first block.
constexpr unsigned kFirstOfPair = (1u << kSimdWidth) - 1;

// The blocks `first` and `first + 1`, lane i of the pair being lane i of the first and lane
// kSimdWidth + i of the second. Always inlined, as the one-block test is in its loop.
[[gnu::always_inline]] inline PairHits intersectBlockPair(const TriangleBlock* first, const RayLanesOf<PairLanes>& ray,
                                                          Real tMax) {
    return mollerTrumboreLanes<PairLanes, kPairLanes>(
        [&](auto component, int axis) {
            return simd_avx2::loadHalves((first[0].*component)[axis], (first[1].*component)[axis]);
        },
        ray, tMax);
}

}  // namespace

}  // namespace rt::RT_LEVEL_NAMESPACE
#endif

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

// Nearest hit: each block's hits are taken in lane order, as the scalar loop took the
// triangles, each only if nearer than the nearest so far (a lane before it may have come nearer)
// and, in a scene with a hit filter (cut-outs, single-sided materials), only if it accepts it.
// A pair of blocks is the same: its second block is tested with the nearest t from before the
// first's hits, and its hits that the first's then beat are dropped here.
template <SimdLevel level>
void SplitTree::searchNearest(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin, Real tMax,
                              Hit& nearest, RayCounters& counters) const {
    const RayLanes lanes(ray);
#if RT_BLOCK_PAIRS
    const RayLanesOf<RT_LEVEL_LANES::PairLanes> pairLanes(ray);
#endif
    const HitFilter* filter = filter_;
    std::uint64_t tests = 0;  // in a register; added to the caller's counters once
    // The hits of the blocks from `first` on (one block, or a pair), lane i in block i / kSimdWidth.
    const auto take = [&](const TriangleBlock* first, const auto& hits) {
        for (unsigned bits = hits.lanes; bits != 0; bits &= bits - 1) {
            const int lane = std::countr_zero(bits);
            if (!(hits.t[lane] < nearest.t)) continue;
            const Hit candidate{hits.t[lane], first[lane / kSimdWidth].id[lane % kSimdWidth], hits.u[lane],
                                hits.v[lane]};
            if (filter && !filter->accepts(ray, candidate)) continue;
            nearest = candidate;
        }
    };
    traverse(
        ray, invDir, node, tMin, tMax, nearest.t,
        counters, [&](const PrimitiveView& prims, const LeafPrimitives& leaf) __attribute__((always_inline)) {
            tests += leaf.triangles + leaf.others;
            const TriangleBlock* blocks = leaf.blocks();
            std::uint32_t b = 0;
#if RT_BLOCK_PAIRS
            for (; b + 2 <= leaf.blockCount(); b += 2)
                take(blocks + b, RT_LEVEL_LANES::intersectBlockPair(blocks + b, pairLanes, nearest.t));
#endif
            for (; b < leaf.blockCount(); ++b) take(blocks + b, intersectBlock(blocks[b], lanes, nearest.t));
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

// Any hit before `rayTMax`, the whole shadow ray's end, in the subtree at `node`. The triangles
// are counted block by block up to the first that blocks; a pair of blocks is counted as its two
// blocks would be, the second only if the first does not block.
template <SimdLevel level>
bool SplitTree::searchBlocker(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin, Real tMax,
                              Real rayTMax, RayCounters& counters) const {
    const RayLanes lanes(ray);
#if RT_BLOCK_PAIRS
    const RayLanesOf<RT_LEVEL_LANES::PairLanes> pairLanes(ray);
#endif
    std::uint64_t tests = 0;
    bool found = false;
    const HitFilter* filter = filter_;
    // Whether the hits `bits` of the blocks from `first` on count (lane i in block i / kSimdWidth):
    // any of them without a filter, else one the filter accepts.
    const auto counts = [&](const TriangleBlock* first, const auto& hits, unsigned bits) {
        if (!filter) return bits != 0;
        for (; bits != 0; bits &= bits - 1) {
            const int lane = std::countr_zero(bits);
            const Hit hit{hits.t[lane], first[lane / kSimdWidth].id[lane % kSimdWidth], hits.u[lane], hits.v[lane]};
            if (filter->accepts(ray, hit)) return true;
        }
        return false;
    };
    traverse(
        ray, invDir, node, tMin, tMax, rayTMax,
        counters, [&](const PrimitiveView& prims, const LeafPrimitives& leaf) __attribute__((always_inline)) {
            const TriangleBlock* blocks = leaf.blocks();
            const auto blockTests = [&](std::uint32_t b) {
                return std::min<std::uint32_t>(kSimdWidth, leaf.triangles - b * kSimdWidth);
            };
            std::uint32_t b = 0;
#if RT_BLOCK_PAIRS
            for (; b + 2 <= leaf.blockCount(); b += 2) {
                const auto hits = RT_LEVEL_LANES::intersectBlockPair(blocks + b, pairLanes, rayTMax);
                tests += blockTests(b);
                if (counts(blocks + b, hits, hits.lanes & RT_LEVEL_LANES::kFirstOfPair)) return found = true;
                tests += blockTests(b + 1);
                if (counts(blocks + b, hits, hits.lanes & ~RT_LEVEL_LANES::kFirstOfPair)) return found = true;
            }
#endif
            for (; b < leaf.blockCount(); ++b) {
                tests += blockTests(b);
                const BlockHits hits = intersectBlock(blocks[b], lanes, rayTMax);
                if (counts(blocks + b, hits, hits.lanes)) return found = true;
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

template void SplitTree::searchNearest<RT_LEVEL>(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin,
                                                 Real tMax, Hit& nearest, RayCounters& counters) const;
template bool SplitTree::searchBlocker<RT_LEVEL>(const Ray& ray, const Vec3& invDir, std::uint32_t node, Real tMin,
                                                 Real tMax, Real rayTMax, RayCounters& counters) const;

}  // namespace rt

RT_LEVEL_END
