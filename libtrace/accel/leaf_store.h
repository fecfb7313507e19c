// The leaves of the trees and of the BVH as the traversals read them (issue 14, issue 37): each
// non-empty leaf one LeafPrimitives record followed by its triangles and spheres in SIMD blocks
// and the ids of its other primitives, all leaves in one array of 16-byte units. The KD and BSP
// trees (accel/split_tree.h) and the BVH (accel/bvh_tree.h) lay their leaves out here alike, and
// test them with the same loops (accel/leaf_tests.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>

#include "accel/settings.h"
#include "core/default_init.h"
#include "geometry/primitives.h"
#include "geometry/sphere_block.h"
#include "geometry/triangle_block.h"
#include "geometry/watertight_triangle.h"

namespace rt {

// A non-empty leaf as the traversal reads it, in one piece of memory: this 16-byte record, then its
// triangles, copied in blocks of kSimdWidth (two with Real = double, four with float;
// geometry/triangle_block.h) so that they are read in sequence and tested together, then its
// spheres likewise (geometry/sphere_block.h), then the ids of its other primitives (padded to 16
// bytes), tested one by one through the PrimitiveView. The record and the first block lie side by
// side, so the traversal fetches them together: the block's address does not wait for the record.
struct alignas(16) LeafPrimitives {
    std::uint32_t triangles = 0, spheres = 0, others = 0;

    std::uint32_t count() const { return triangles + spheres + others; }
    std::uint32_t blockCount() const { return (triangles + kSimdWidth - 1) / kSimdWidth; }
    std::uint32_t sphereBlockCount() const { return (spheres + kSimdWidth - 1) / kSimdWidth; }
    // The 16-byte units the leaf takes: this record, its blocks and its other ids, padded.
    std::size_t units() const {
        return 1 + (blockCount() * sizeof(TriangleBlock) + sphereBlockCount() * sizeof(SphereBlock)) / 16 +
               (others + 3) / 4;
    }
    const TriangleBlock* blocks() const { return std::launder(reinterpret_cast<const TriangleBlock*>(this + 1)); }
    // The triangle blocks of a store of TriangleTest::Watertight, in the same bytes as blocks().
    const VertexBlock* vertexBlocks() const { return std::launder(reinterpret_cast<const VertexBlock*>(this + 1)); }
    const SphereBlock* sphereBlocks() const {
        return std::launder(reinterpret_cast<const SphereBlock*>(blocks() + blockCount()));
    }
    const std::uint32_t* otherIds() const {
        return std::launder(reinterpret_cast<const std::uint32_t*>(sphereBlocks() + sphereBlockCount()));
    }
};
// A leaf's triangle blocks as the triangle test `test` reads them.
template <TriangleTest test>
auto triangleBlocks(const LeafPrimitives& leaf) {
    if constexpr (test == TriangleTest::Watertight)
        return leaf.vertexBlocks();
    else
        return leaf.blocks();
}

static_assert(sizeof(LeafPrimitives) == 16 && sizeof(TriangleBlock) % 16 == 0 && alignof(TriangleBlock) <= 16 &&
              sizeof(SphereBlock) % 16 == 0 && alignof(SphereBlock) <= 16);
// What a traversal fetches ahead of a leaf: its record and first block.
inline constexpr std::size_t kLeafPrefetchBytes = sizeof(LeafPrimitives) + sizeof(TriangleBlock);

// The leaves of one structure: sized first (units), then written leaf by leaf, possibly in
// parallel at offsets the caller summed (write). Its triangles are blocks for `test`:
// TriangleBlocks for Moller-Trumbore, VertexBlocks for the watertight test.
class LeafStore {
public:
    explicit LeafStore(TriangleTest test) : test_(test) {}
    TriangleTest triangleTest() const { return test_; }

    // The record of the leaf of the `count` primitives `ids`: how many are triangles and spheres.
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
