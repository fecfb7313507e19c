#include "accel/leaf_store.h"

#include <cstring>
#include <tuple>
#include <type_traits>
#include <utility>

namespace rt {

namespace {

// The place of kind K among the kinds with blocks.
template <class K, std::size_t I = 0>
constexpr std::size_t blockKindIndex() {
    if constexpr (std::is_same_v<std::tuple_element_t<I, BlockKinds>, K>)
        return I;
    else
        return blockKindIndex<K, I + 1>();
}

// Copies the blocks of one kind one by one to `out`, each full block or the last as it is filled:
// Block::set(lane, primitive, id) fills a lane.
template <class Block>
class BlockWriter {
public:
    BlockWriter() = default;
    BlockWriter(std::byte* out, std::uint32_t count) : out_(out), count_(count) {}
    template <class Kind>
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
    std::byte* out_ = nullptr;
    std::uint32_t count_ = 0, written_ = 0;
    Block block_;
};

// The writers of the blocks of each kind with a block, as a store of triangle test `test` holds them.
template <TriangleTest test, class Indices = std::make_index_sequence<kBlockKindCount>>
struct BlockWritersOf;
template <TriangleTest test, std::size_t... I>
struct BlockWritersOf<test, std::index_sequence<I...>> {
    using type = std::tuple<BlockWriter<StoredBlock<test, I>>...>;
};

// LeafStore::write for the triangle test `test`: the record, then each kind's blocks, then the
// other ids, from `out` on.
template <TriangleTest test>
void writeLeaf(const Primitives& prims, const std::uint32_t* ids, const LeafPrimitives& sizes, std::byte* out) {
    std::memcpy(out, &sizes, sizeof(sizes));
    std::byte* const blocks = out + sizeof(LeafPrimitives);
    typename BlockWritersOf<test>::type writers;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((std::get<I>(writers) = {blocks + sizes.blockBytesBefore<I>(), sizes.blocked[I]}), ...);
    }
    (std::make_index_sequence<kBlockKindCount>{});
    std::byte* others = blocks + sizes.blockBytesBefore<kBlockKindCount>();
    const PrimitiveView view = prims.view();
    for (std::uint32_t i = 0; i < sizes.count(); ++i) {
        view.visit(ids[i], [&]<class K>(const K& primitive) {
            if constexpr (BlockTested<K>) {
                std::get<blockKindIndex<K>()>(writers).add(primitive, ids[i]);
            } else {
                std::memcpy(others, &ids[i], sizeof(std::uint32_t));
                others += sizeof(std::uint32_t);
            }
        });
    }
}

}  // namespace

LeafPrimitives LeafStore::sizesOf(const Primitives& prims, const std::uint32_t* ids, std::uint32_t count) {
    LeafPrimitives sizes;
    const PrimitiveView view = prims.view();
    for (std::uint32_t i = 0; i < count; ++i) {
        view.visit(ids[i], [&]<class K>(const K&) {
            if constexpr (BlockTested<K>)
                ++sizes.blocked[blockKindIndex<K>()];
            else
                ++sizes.others;
        });
    }
    return sizes;
}

// (Copying the bytes of these trivially copyable types creates them there.)
void LeafStore::write(const Primitives& prims, const std::uint32_t* ids, const LeafPrimitives& sizes, std::size_t at) {
    if (test_ == TriangleTest::Watertight)
        writeLeaf<TriangleTest::Watertight>(prims, ids, sizes, units_[at].bytes);
    else
        writeLeaf<TriangleTest::MollerTrumbore>(prims, ids, sizes, units_[at].bytes);
}

}  // namespace rt
