// The leaves of the trees and of the BVH as the traversals read them (issue 14, issue 37): each
// non-empty leaf one LeafPrimitives record followed by its primitives of each kind with a block
// (geometry/leaf_block.h: triangles, spheres, ...) in SIMD blocks, kind after kind in list order,
// and the ids of its other primitives, all leaves in one array of 16-byte units. The KD and BSP
// trees (accel/split_tree.h) and the BVH (accel/bvh_tree.h) lay their leaves out here alike, and
// test them with the same loops (accel/leaf_tests.h). Neither names a kind: a new kind with a
// block is laid out and tested in blocks, one without is tested by id. The one exception is the
// structure's triangle test (TriangleTest): with the watertight test the triangles' blocks are
// VertexBlocks (geometry/watertight_triangle.h), in the bytes of their TriangleBlocks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>
#include <tuple>
#include <type_traits>
#include <utility>

#include "accel/settings.h"
#include "core/default_init.h"
#include "geometry/primitives.h"
#include "geometry/watertight_triangle.h"

namespace rt {

// The block type of the I-th kind with a block (geometry/primitive_kinds.h, BlockKinds).
template <std::size_t I>
using BlockOfKind = LeafBlock<std::tuple_element_t<I, BlockKinds>>;
// The block of the I-th kind with a block in the leaves of a structure of triangle test `test`:
// VertexBlocks for the triangles with the watertight test, else the kind's block.
template <TriangleTest test, std::size_t I>
using StoredBlock =
    std::conditional_t<test == TriangleTest::Watertight && std::is_same_v<BlockOfKind<I>, TriangleBlock>, VertexBlock,
                       BlockOfKind<I>>;

// A non-empty leaf as the traversal reads it, in one piece of memory: this 16-byte record, then the
// primitives of each kind with a block, copied kSimdWidth to a block (two with Real = double, four
// with float) so that they are read in sequence and tested together, then the ids of its other
// primitives (padded to 16 bytes), tested one by one through the PrimitiveView. The record and the
// first block lie side by side, so the traversal fetches them together: the block's address does
// not wait for the record.
struct alignas(16) LeafPrimitives {
    std::uint32_t blocked[kBlockKindCount] = {};  // of each kind with a block, in BlockKinds order
    std::uint32_t others = 0;

    std::uint32_t count() const {
        std::uint32_t n = others;
        for (const std::uint32_t k : blocked) n += k;
        return n;
    }
    // The blocks of the I-th kind with a block, and how many, in a store of triangle test `test`.
    template <std::size_t I>
    std::uint32_t blockCount() const {
        return (blocked[I] + kSimdWidth - 1) / kSimdWidth;
    }
    template <TriangleTest test, std::size_t I>
    const StoredBlock<test, I>* blocks() const {
        return std::launder(reinterpret_cast<const StoredBlock<test, I>*>(afterRecord() + blockBytesBefore<I>()));
    }
    const std::uint32_t* otherIds() const {
        return std::launder(
            reinterpret_cast<const std::uint32_t*>(afterRecord() + blockBytesBefore<kBlockKindCount>()));
    }
    // The 16-byte units the leaf takes: this record, its blocks and its other ids, padded.
    std::size_t units() const { return 1 + blockBytesBefore<kBlockKindCount>() / 16 + (others + 3) / 4; }
    // The bytes of the blocks of the kinds before the I-th: where its blocks start after the record.
    template <std::size_t I>
    std::size_t blockBytesBefore() const {
        if constexpr (I == 0)
            return 0;
        else
            return blockBytesBefore<I - 1>() + blockCount<I - 1>() * sizeof(BlockOfKind<I - 1>);
    }

private:
    const std::byte* afterRecord() const { return reinterpret_cast<const std::byte*>(this + 1); }
};
static_assert(sizeof(LeafPrimitives) == 16, "a leaf's record counts at most three kinds with blocks");
static_assert([]<std::size_t... I>(std::index_sequence<I...>) {
    constexpr TriangleTest kWatertight = TriangleTest::Watertight;
    return ((sizeof(BlockOfKind<I>) % 16 == 0 && alignof(BlockOfKind<I>) <= 16 &&
             sizeof(StoredBlock<kWatertight, I>) == sizeof(BlockOfKind<I>)) &&
            ...);
}(std::make_index_sequence<kBlockKindCount>{}));
// What a traversal fetches ahead of a leaf: its record and first block.
inline constexpr std::size_t kLeafPrefetchBytes = sizeof(LeafPrimitives) + sizeof(BlockOfKind<0>);

// The leaves of one structure: sized first (units), then written leaf by leaf, possibly in
// parallel at offsets the caller summed (write). Its triangles are blocks for `test`:
// TriangleBlocks for Moller-Trumbore, VertexBlocks for the watertight test (StoredBlock).
class LeafStore {
public:
    explicit LeafStore(TriangleTest test) : test_(test) {}
    TriangleTest triangleTest() const { return test_; }

    // The record of the leaf of the `count` primitives `ids`: how many are of each kind with a block.
    static LeafPrimitives sizesOf(const Primitives& prims, const std::uint32_t* ids, std::uint32_t count);

    void resize(std::size_t units) { units_.resize(units); }
    // Writes the leaf of the primitives `ids` (its record `sizes`) from unit `at` on. Each kind keeps
    // its order among itself, and the kinds are tested in that order; the order decides only
    // between hits at exactly the same distance.
    void write(const Primitives& prims, const std::uint32_t* ids, const LeafPrimitives& sizes, std::size_t at);

    const LeafPrimitives& at(std::uint32_t unit) const {
        return *std::launder(reinterpret_cast<const LeafPrimitives*>(&units_[unit]));
    }
    // The address of unit `unit`, for prefetching (it need not hold a leaf).
    std::uintptr_t address(std::uint32_t unit) const {
        return std::uintptr_t(units_.data()) + std::uintptr_t(unit) * sizeof(Unit);
    }
    std::size_t bytes() const { return units_.size() * sizeof(Unit); }

private:
    struct alignas(16) Unit {
        std::byte bytes[16];
    };
    TriangleTest test_;
    UninitializedVector<Unit> units_;
};

}  // namespace rt
