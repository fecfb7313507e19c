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

namespace rt::RT_LEVEL_NAMESPACE {

namespace {

#if RT_BLOCK_PAIRS
struct PairLanes {
    using Type = simd_avx2::RealLanes;
    static Type all(Real x) { return simd_avx2::broadcast(x); }
};
static_assert(2 * kSimdWidth == simd_avx2::kLanes);

// The blocks `first` and `first + 1`, lane i of the pair being lane i of the first and lane
// kSimdWidth + i of the second. Always inlined, as the one-block test is in its loop.
[[gnu::always_inline]] inline LaneHits<2 * kSimdWidth> intersectBlockPair(const TriangleBlock* first,
                                                                          const RayLanesOf<PairLanes>& ray, Real tMax) {
    return mollerTrumboreLanes<PairLanes, 2 * kSimdWidth>(
        [&](auto component, int axis) {
            return simd_avx2::loadHalves((first[0].*component)[axis], (first[1].*component)[axis]);
        },
        ray, tMax);
}
[[gnu::always_inline]] inline LaneHits<2 * kSimdWidth> intersectBlockPair(const SphereBlock* first,
                                                                          const RayLanesOf<PairLanes>& ray, Real tMax) {
    return sphereLanes<PairLanes, 2 * kSimdWidth>(
        [&](int axis) {
            return axis < 0 ? simd_avx2::loadHalves(first[0].r2, first[1].r2)
                            : simd_avx2::loadHalves(first[0].center[axis], first[1].center[axis]);
        },
        ray, tMax);
}
#endif

// A leaf's blocks of one kind (triangles or spheres) tested against one ray, in order: two at a
// time where the level has pairs, the last alone when their number is odd.
class BlockTests {
public:
    explicit BlockTests(const Ray& ray)
        : one_(ray)
#if RT_BLOCK_PAIRS
          ,
          two_(ray)
#endif
    {
    }

    // visit(blocks + b, b, hits, count) for each group of `count` of the `blockCount` blocks from
    // block b on, lane i of `hits` in block b + i / kSimdWidth, each group tested against tMax as
    // it is then; stops when visit returns true, and returns whether it did.
    template <class Block, typename Visit>
    [[gnu::always_inline]] bool operator()(const Block* blocks, std::uint32_t blockCount, const Real& tMax,
                                           const Visit& visit) const {
        std::uint32_t b = 0;
#if RT_BLOCK_PAIRS
        for (; b + 2 <= blockCount; b += 2)
            if (visit(blocks + b, b, intersectBlockPair(blocks + b, two_, tMax), 2)) return true;
#endif
        for (; b < blockCount; ++b)
            if (visit(blocks + b, b, intersectBlock(blocks[b], one_, tMax), 1)) return true;
        return false;
    }

private:
    RayLanes one_;
#if RT_BLOCK_PAIRS
    RayLanesOf<PairLanes> two_;
#endif
};

// Lane `lane` of the hits of the blocks from `first` on as a Hit.
template <class Block, int N>
Hit laneHit(const Block* first, const LaneHits<N>& hits, int lane) {
    return {hits.t[lane], first[lane / kSimdWidth].id[lane % kSimdWidth], hits.u[lane], hits.v[lane]};
}

}  // namespace

}  // namespace rt::RT_LEVEL_NAMESPACE

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
    const RT_LEVEL_LANES::BlockTests testBlocks(ray);
    const HitFilter* filter = filter_;
    std::uint64_t tests = 0;  // in a register; added to the caller's counters once
    traverse(
        ray, invDir, node, tMin, tMax, nearest.t,
        counters, [&](const PrimitiveView& prims, const LeafPrimitives& leaf) __attribute__((always_inline)) {
            tests += leaf.triangles + leaf.spheres + leaf.others;
            const auto takeNearest = [&](const auto* first, std::uint32_t, const auto& hits, int) {
                for (unsigned bits = hits.lanes; bits != 0; bits &= bits - 1) {
                    const int lane = std::countr_zero(bits);
                    if (!(hits.t[lane] < nearest.t)) continue;
                    const Hit candidate = RT_LEVEL_LANES::laneHit(first, hits, lane);
                    if (filter && !filter->accepts(ray, candidate)) continue;
                    nearest = candidate;
                }
                return false;
            };
            testBlocks(leaf.blocks(), leaf.blockCount(), nearest.t, takeNearest);
            testBlocks(leaf.sphereBlocks(), leaf.sphereBlockCount(), nearest.t, takeNearest);
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
    const RT_LEVEL_LANES::BlockTests testBlocks(ray);
    std::uint64_t tests = 0;
    bool found = false;
    const HitFilter* filter = filter_;
    traverse(
        ray, invDir, node, tMin, tMax, rayTMax,
        counters, [&](const PrimitiveView& prims, const LeafPrimitives& leaf) __attribute__((always_inline)) {
            // Block by block within a group of the `total` primitives of a kind: its tests counted,
            // then whether one of its hits counts (any without a filter, else one the filter accepts).
            const auto blockedIn = [&](std::uint32_t total) {
                return [&, total](const auto* first, std::uint32_t firstIndex, const auto& hits, int count) {
                    for (int k = 0; k < count; ++k) {
                        const std::uint32_t b = firstIndex + std::uint32_t(k);
                        tests += std::min<std::uint32_t>(kSimdWidth, total - b * kSimdWidth);
                        unsigned bits = hits.lanes & (((1u << kSimdWidth) - 1) << (k * kSimdWidth));
                        if (!filter && bits != 0) return true;
                        for (; bits != 0; bits &= bits - 1)
                            if (filter->accepts(ray, RT_LEVEL_LANES::laneHit(first, hits, std::countr_zero(bits))))
                                return true;
                    }
                    return false;
                };
            };
            if (testBlocks(leaf.blocks(), leaf.blockCount(), rayTMax, blockedIn(leaf.triangles)) ||
                testBlocks(leaf.sphereBlocks(), leaf.sphereBlockCount(), rayTMax, blockedIn(leaf.spheres)))
                return found = true;
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
