// The single-ray tests of one leaf (accel/leaf_store.h), shared by the KD and BSP trees
// (accel/kd_single.cpp) and the BVH (accel/bvh_traversal.cpp): a leaf's blocks of each kind with a
// block (geometry/leaf_block.h) tested on the level's lanes, kind after kind, its other primitives
// one by one; the triangles by the structure's triangle test (TriangleTest). Included last by a
// file compiled once per level (accel/simd_level.h), in an include block of its own: what it
// defines lies in that level's region and namespace.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "accel/leaf_store.h"
#include "geometry/hit_filter.h"

// Last, in a block of its own (clang-format sorts a block): the level's region starts here.
#include "accel/simd_level.h"

// AVX2 and AVX-512 test a leaf's blocks two at a time, in one register twice SSE2's width (four
// doubles or eight floats; AVX-512 takes AVX2's register, compiled for its own level): one test's
// instructions for two blocks' primitives, each lane computing what it computes in a block alone.
#define RT_BLOCK_PAIRS (RT_LEVEL_AVX2 || RT_LEVEL_AVX512)

namespace rt::RT_LEVEL_NAMESPACE {

// Calls f(std::integral_constant<std::size_t, I>{}) for the I-th kind with a block
// (geometry/primitive_kinds.h, BlockKinds), in list order, while f returns false; returns whether
// one returned true. Here, in the level's region, so that the tests it calls are compiled for the
// level and inlined (a helper compiled for the base level could not inline them).
template <class F>
[[gnu::always_inline]] inline bool anyBlockKind(const F& f) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) __attribute__((always_inline)) {
        return (f(std::integral_constant<std::size_t, I>{}) || ...);
    }
    (std::make_index_sequence<kBlockKindCount>{});
}

#if RT_BLOCK_PAIRS
struct PairLanes {
    using Type = simd_avx2::RealLanes;
    static constexpr int kWidth = simd_avx2::kLanes;
    static Type all(Real x) { return simd_avx2::broadcast(x); }
    static Type load(const Real* p) { return simd_avx2::loadLanes(p); }
};
static_assert(2 * kSimdWidth == simd_avx2::kLanes);

// The blocks `first` and `first + 1`, lane i of the pair being lane i of the first and lane
// kSimdWidth + i of the second: one test's instructions for both. Always inlined, as the one-block
// test is in its loop.
template <class Block>
[[gnu::always_inline]] inline LaneHits<2 * kSimdWidth> intersectBlockPair(
    const Block* first, const typename Block::template RayOf<PairLanes>& ray, Real tMax) {
    return LaneHits<2 * kSimdWidth>::of(Block::template test<PairLanes>(
        [&](auto row) { return simd_avx2::loadHalves(row(first[0]), row(first[1])); }, ray, PairLanes::all(tMax)));
}
#endif

// A leaf's blocks of one kind tested against one ray, in order: two at a time where the level has
// pairs, the last alone when their number is odd, each on the ray as its test takes it
// (Block::RayOf): with `test` Watertight the triangles are VertexBlocks, tested on the ray sheared
// (geometry/watertight_triangle.h), found once per ray here.
template <TriangleTest test>
class BlockTests {
public:
    explicit BlockTests(const Ray& ray)
        : one_(ray),
#if RT_BLOCK_PAIRS
          two_(ray),
#endif
          sheared_(ray) {
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
            if (visit(blocks + b, b, intersectBlockPair(blocks + b, pairRay<Block>(), tMax), 2)) return true;
#endif
        for (; b < blockCount; ++b)
            if (visit(blocks + b, b, intersectBlock(blocks[b], oneRay<Block>(), tMax), 1)) return true;
        return false;
    }

private:
    // The ray as Block's test takes it: sheared for VertexBlocks, else as it is.
    template <class Block>
    [[gnu::always_inline]] const auto& oneRay() const {
        if constexpr (std::is_same_v<Block, VertexBlock>)
            return sheared_.one;
        else
            return one_;
    }
#if RT_BLOCK_PAIRS
    template <class Block>
    [[gnu::always_inline]] const auto& pairRay() const {
        if constexpr (std::is_same_v<Block, VertexBlock>)
            return sheared_.two;
        else
            return two_;
    }
#endif

    // The sheared ray on the lanes of one block and of a pair, for the watertight test only.
    struct Sheared {
        explicit Sheared(const Ray& ray) : Sheared(ShearedRay(ray)) {}
        explicit Sheared(const ShearedRay& ray)
            : one(ray)
#if RT_BLOCK_PAIRS
              ,
              two(ray)
#endif
        {
        }
        ShearedRayLanes one;
#if RT_BLOCK_PAIRS
        ShearedRayLanesOf<PairLanes> two;
#endif
    };
    struct NotSheared {
        explicit NotSheared(const Ray&) {}
    };

    RayLanes one_;
#if RT_BLOCK_PAIRS
    RayLanesOf<PairLanes> two_;
#endif
    [[no_unique_address]] std::conditional_t<test == TriangleTest::Watertight, Sheared, NotSheared> sheared_;
};

// Lane `lane` of the hits of the blocks from `first` on as a Hit.
template <class Block, int N>
Hit laneHit(const Block* first, const LaneHits<N>& hits, int lane) {
    return {hits.t[lane], first[lane / kSimdWidth].id[lane % kSimdWidth], hits.u[lane], hits.v[lane]};
}

// Nearest hit in `leaf`: each block's hits are taken in lane order, as the scalar loop took the
// triangles, each only if nearer than the nearest so far (a lane before it may have come nearer)
// and, in a scene with a hit filter (cut-outs, single-sided materials), only if it accepts it.
// A pair of blocks is the same: its second block is tested with the nearest t from before the
// first's hits, and its hits that the first's then beat are dropped here. Adds its tests to `tests`.
// With `noteTies` (the BVH's packets, accel/bvh_packet.cpp, whose rays meet their leaves in another
// order than alone) the leaf also looks for hits exactly as near as the nearest so far, which the
// tie rule gives to the one found first, and sets `*tied` when it meets one: the nearest is then
// what this order found, not necessarily what the ray's own order finds. A hit at exactly the
// ray's tMax sets it too (no harm: the caller traces a tied ray again alone).
template <TriangleTest test, bool noteTies = false>
[[gnu::always_inline]] inline void nearestInLeaf(const BlockTests<test>& testBlocks, const PrimitiveView& prims,
                                                 const LeafPrimitives& leaf, const Ray& ray, const HitFilter* filter,
                                                 Hit& nearest, std::uint64_t& tests, bool* tied = nullptr) {
    tests += leaf.count();
    // The blocks' limit: the nearest t, or with noteTies the next value up, so that a hit at the
    // nearest t is found too.
    Real tieLimit = noteTies ? std::nextafter(nearest.t, kInfinity) : 0;
    const Real& limit = noteTies ? tieLimit : nearest.t;
    const auto take = [&](const Hit& candidate) {
        nearest = candidate;
        if constexpr (noteTies) tieLimit = std::nextafter(nearest.t, kInfinity);
    };
    const auto takeNearest = [&](const auto* first, std::uint32_t, const auto& hits, int) {
        for (unsigned bits = hits.lanes; bits != 0; bits &= bits - 1) {
            const int lane = std::countr_zero(bits);
            if (!(hits.t[lane] < nearest.t)) {
                if constexpr (noteTies) *tied |= hits.t[lane] == nearest.t;
                continue;
            }
            const Hit candidate = laneHit(first, hits, lane);
            if (filter && !filter->accepts(ray, candidate)) continue;
            take(candidate);
        }
        return false;
    };
    anyBlockKind([&](auto kind) __attribute__((always_inline)) {
        return testBlocks(leaf.blocks<test, kind>(), leaf.blockCount<kind>(), limit, takeNearest);
    });
    const std::uint32_t* otherIds = leaf.otherIds();
    for (std::uint32_t i = 0; i < leaf.others; ++i) {
        if constexpr (noteTies) {
            Hit candidate;
            if (!prims.intersect(otherIds[i], ray, tieLimit, candidate)) continue;
            if (candidate.t == nearest.t)
                *tied = true;
            else if (!filter || filter->accepts(ray, candidate))
                take(candidate);
        } else if (filter) {
            intersectFiltered(prims, otherIds[i], ray, *filter, nearest);
        } else {
            prims.intersect(otherIds[i], ray, nearest.t, nearest);
        }
    }
}

// Whether anything in `leaf` blocks the ray before `rayTMax`. The blocks are counted in `tests`
// block by block, kind after kind, up to the first that blocks; a pair of blocks is counted as its two blocks would
// be, the second only if the first does not block.
template <TriangleTest test>
[[gnu::always_inline]] inline bool blockerInLeaf(const BlockTests<test>& testBlocks, const PrimitiveView& prims,
                                                 const LeafPrimitives& leaf, const Ray& ray, Real rayTMax,
                                                 const HitFilter* filter, std::uint64_t& tests) {
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
                    if (filter->accepts(ray, laneHit(first, hits, std::countr_zero(bits)))) return true;
            }
            return false;
        };
    };
    if (anyBlockKind([&](auto kind) __attribute__((always_inline)) {
            return testBlocks(leaf.blocks<test, kind>(), leaf.blockCount<kind>(), rayTMax,
                              blockedIn(leaf.blocked[kind]));
        }))
        return true;
    const std::uint32_t* otherIds = leaf.otherIds();
    for (std::uint32_t i = 0; i < leaf.others; ++i) {
        ++tests;
        const bool hits = filter ? occludesFiltered(prims, otherIds[i], ray, rayTMax, *filter)
                                 : prims.intersectsAny(otherIds[i], ray, rayTMax);
        if (hits) return true;
    }
    return false;
}

}  // namespace rt::RT_LEVEL_NAMESPACE
