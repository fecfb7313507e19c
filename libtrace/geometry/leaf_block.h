// The optional block trait of a primitive kind, and the lanes its block test runs on. The trees'
// leaves (accel/leaf_store.h) hold the primitives of a kind that declares a block kSimdWidth at a
// time, component by component, so that a leaf's primitives of that kind are read in sequence and
// tested together; a kind without one is tested one at a time through PrimitiveView. As Embree
// selects a leaf intersector per primitive type, the leaves and their loops ask only this trait:
// a new kind with a block takes the fast path with no change to the accelerators.
//
// A kind K declares its block by specializing LeafBlockOf<K> in its own header (geometry/
// triangle_block.h, sphere_block.h), which geometry/primitive_kinds.h includes. The block
// type B provides:
//   B()                               every lane unused: never hit, id kNoPrimitive
//   void set(lane, const K&, id)      fills one lane
//   std::uint32_t id[kSimdWidth]      the primitive ids of the lanes
//   template <class Lanes> using RayOf    the ray as its test takes it on Lanes: RayLanesOf (below),
//                                     or a form of the ray found once per ray (VertexBlock's sheared ray)
//   static LaneTest<L> test<Lanes>(load, ray, limit)
//       the kind's ray test on Lanes (below) of the ray as RayOf<Lanes>, the hits with 0 < t < limit lane by lane, with
//       the operations of the kind's scalar intersect() in its order so that a lane has its bits. It reads its lanes
//       through load(row), row(const B&) giving one of the block's arrays of kSimdWidth Reals: the caller decides what
//       a lane is. A leaf's block is one block's primitives against one ray (intersectBlock), a pair of blocks on twice
//       the lanes (accel/leaf_tests.h), or one primitive in every lane against a packet's rays (accel/kd_packet.cpp).
//       Always inlined, so that it is compiled for the caller's level.
// B is trivially copyable, its size a multiple of 16 bytes and its alignment at most 16.
#pragma once

#include <cstdint>
#include <type_traits>

#include "core/ray.h"
#include "core/simd.h"

namespace rt {

template <class K>
struct LeafBlockOf {
    using type = void;  // no block: tested one at a time
};
template <class K>
using LeafBlock = typename LeafBlockOf<K>::type;
template <class K>
concept BlockTested = !std::is_void_v<LeafBlock<K>>;

// A set of lanes a block test runs on: Type, a register of kWidth Real lanes with core/simd.h's
// operations (found by argument-dependent lookup), all(x), x in every lane, and load(p), the lanes
// from p (aligned to 64 bytes). BaseLanes is simd_base's register, one block's width;
// accel/leaf_tests.h adds a register two blocks wide and accel/kd_packet.cpp the level's register.
struct BaseLanes {
    using Type = RealLanes;
    static constexpr int kWidth = kSimdWidth;
    static RealLanes all(Real x) { return broadcast(x); }
    static RealLanes load(const Real* p) { return loadLanes(p); }
};

// The ray's origin and direction, component by component: one ray in every lane (a leaf's test),
// or a lane per ray (a packet's).
template <class Lanes>
struct RayLanesOf {
    typename Lanes::Type origin[3], direction[3];
    RayLanesOf() = default;
    // Always inlined, as the block tests are.
    [[gnu::always_inline]] explicit RayLanesOf(const Ray& ray) {
        for (int axis = 0; axis < 3; ++axis) {
            origin[axis] = Lanes::all(ray.origin[axis]);
            direction[axis] = Lanes::all(ray.direction[axis]);
        }
    }
};
using RayLanes = RayLanesOf<BaseLanes>;

// What a block test finds, lane by lane: the lanes that hit (all-ones masks), and t, u and v.
template <class L>
struct LaneTest {
    L hit, t, u, v;
};

// The selector of row `axis` of the block's array `member` (a Real[3][kSimdWidth]), for load(row).
template <class Block, class Member>
constexpr auto blockRow(Member member, int axis) {
    return [=](const Block& b) -> const Real* { return (b.*member)[axis]; };
}

// One lane per primitive of the hits with 0 < t < tMax, as the kind's scalar test decides them.
template <int N>
struct LaneHits {
    unsigned lanes = 0;  // bit i: lane i hits
    Real t[N], u[N], v[N];

    // The hits of the lanes set in `test.hit`, their t, u and v stored only if there are any.
    template <class L>
    [[gnu::always_inline]] static LaneHits of(const LaneTest<L>& test) {
        LaneHits hits;
        hits.lanes = laneBits(test.hit);
        if (hits.lanes) {
            storeLanes(hits.t, test.t);
            storeLanes(hits.u, test.u);
            storeLanes(hits.v, test.v);
        }
        return hits;
    }
};
using BlockHits = LaneHits<kSimdWidth>;

// The test on one block's primitives.
template <class Block>
inline BlockHits intersectBlock(const Block& b, const typename Block::template RayOf<BaseLanes>& ray, Real tMax) {
    return BlockHits::of(
        Block::template test<BaseLanes>([&](auto row) { return loadLanes(row(b)); }, ray, broadcast(tMax)));
}

}  // namespace rt
