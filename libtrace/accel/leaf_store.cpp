#include "accel/leaf_store.h"

#include <cstring>
#include <optional>

namespace rt {

LeafPrimitives LeafStore::sizesOf(const Primitives& prims, const std::uint32_t* ids, std::uint32_t count) {
    LeafPrimitives sizes;
    for (std::uint32_t i = 0; i < count; ++i) {
        sizes.triangles += prims.indexIn<Triangle>(ids[i]) ? 1 : 0;
        sizes.spheres += prims.indexIn<Sphere>(ids[i]) ? 1 : 0;
    }
    sizes.others = count - sizes.triangles - sizes.spheres;
    return sizes;
}

namespace {

// Copies the blocks of Kind one by one to `out`, each full block or the last as it is filled:
// set(block, lane, primitive, id) fills a lane.
template <class Block, class Kind>
class BlockWriter {
public:
    BlockWriter(std::byte* out, std::uint32_t count) : out_(out), count_(count) {}
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
    std::byte* out_;
    std::uint32_t count_, written_ = 0;
    Block block_;
};

}  // namespace

// (Copying the bytes of these trivially copyable types creates them there.)
void LeafStore::write(const Primitives& prims, const std::uint32_t* ids, const LeafPrimitives& sizes, std::size_t at) {
    std::byte* out = units_[at].bytes;
    std::memcpy(out, &sizes, sizeof(sizes));
    std::byte* const triangleBlocks = out + sizeof(LeafPrimitives);
    std::byte* const sphereBlocks = triangleBlocks + sizes.blockCount() * sizeof(TriangleBlock);
    std::byte* others = sphereBlocks + sizes.sphereBlockCount() * sizeof(SphereBlock);
    BlockWriter<TriangleBlock, Triangle> triangles(triangleBlocks, sizes.triangles);
    BlockWriter<VertexBlock, Triangle> watertightTriangles(triangleBlocks, sizes.triangles);
    BlockWriter<SphereBlock, Sphere> spheres(sphereBlocks, sizes.spheres);
    for (std::uint32_t i = 0; i < sizes.count(); ++i) {
        if (const std::optional<std::uint32_t> triangle = prims.indexIn<Triangle>(ids[i])) {
            if (test_ == TriangleTest::Watertight)
                watertightTriangles.add(prims.all<Triangle>()[*triangle], ids[i]);
            else
                triangles.add(prims.all<Triangle>()[*triangle], ids[i]);
        } else if (const std::optional<std::uint32_t> sphere = prims.indexIn<Sphere>(ids[i])) {
            spheres.add(prims.all<Sphere>()[*sphere], ids[i]);
        } else {
            std::memcpy(others, &ids[i], sizeof(std::uint32_t));
            others += sizeof(std::uint32_t);
        }
    }
}

}  // namespace rt
