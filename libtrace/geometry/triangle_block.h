// Triangles laid out for the trees' leaves (issue 14), the triangles' block (geometry/leaf_block.h):
// kSimdWidth at a time (core/simd.h), each as a vertex and its two edges (the Moller-Trumbore form),
// component by component. The lanes compute exactly what intersectTriangle (triangle.h) computes,
// operation by operation, so a block's hits have the scalar test's bits.
#pragma once

#include <algorithm>
#include <cstdint>
#include <iterator>

#include "geometry/leaf_block.h"
#include "geometry/triangle.h"

namespace rt {

// Moller-Trumbore with one triangle per lane (see intersectTriangle: the same operations in the
// same order; every lane is computed, the rejections become masks). load(row) gives the lanes of
// one of TriangleBlock's arrays (geometry/leaf_block.h). Always inlined: in a function compiled
// for AVX2 or AVX-512 (core/simd.h) the test is compiled for it too.
template <class Lanes, class Block, class Load>
[[gnu::always_inline]] inline LaneTest<typename Lanes::Type> mollerTrumboreLanes(const Load& load,
                                                                                 const RayLanesOf<Lanes>& ray,
                                                                                 const typename Lanes::Type& limit) {
    using L = typename Lanes::Type;
    const L e1x = load(blockRow<Block>(&Block::e1, 0)), e1y = load(blockRow<Block>(&Block::e1, 1)),
            e1z = load(blockRow<Block>(&Block::e1, 2));
    const L e2x = load(blockRow<Block>(&Block::e2, 0)), e2y = load(blockRow<Block>(&Block::e2, 1)),
            e2z = load(blockRow<Block>(&Block::e2, 2));
    const L &dx = ray.direction[0], &dy = ray.direction[1], &dz = ray.direction[2];
    // p = cross(d, e2), det = dot(e1, p)
    const L px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
    const L det = e1x * px + e1y * py + e1z * pz;
    const L invDet = Lanes::all(1) / det;
    // s = origin - p0, u = dot(s, p) / det
    const L sx = ray.origin[0] - load(blockRow<Block>(&Block::p0, 0)),
            sy = ray.origin[1] - load(blockRow<Block>(&Block::p0, 1)),
            sz = ray.origin[2] - load(blockRow<Block>(&Block::p0, 2));
    LaneTest<L> hits;
    hits.u = (sx * px + sy * py + sz * pz) * invDet;
    // q = cross(s, e1), v = dot(d, q) / det, t = dot(e2, q) / det
    const L qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
    hits.v = (dx * qx + dy * qy + dz * qz) * invDet;
    hits.t = (e2x * qx + e2y * qy + e2z * qz) * invDet;
    const L zero = Lanes::all(0), one = Lanes::all(1);
    const L inside = notEqual(det, zero) & notLessThan(hits.u, zero) & notGreaterThan(hits.u, one) &
                     notLessThan(hits.v, zero) & notGreaterThan(hits.u + hits.v, one);
    hits.hit = inside & lessThan(zero, hits.t) & lessThan(hits.t, limit);
    return hits;
}

struct alignas(16) TriangleBlock {
    static constexpr std::uint32_t kNoPrimitive = ~0u;  // an unused lane: zero edges, never hit
    Real p0[3][kSimdWidth] = {};
    Real e1[3][kSimdWidth] = {};
    Real e2[3][kSimdWidth] = {};
    std::uint32_t id[kSimdWidth];

    TriangleBlock() { std::fill(std::begin(id), std::end(id), kNoPrimitive); }

    void set(int lane, const Triangle& tri, std::uint32_t primitiveId) {
        const Vec3 e1v = tri.p1 - tri.p0, e2v = tri.p2 - tri.p0;
        for (int axis = 0; axis < 3; ++axis) {
            p0[axis][lane] = tri.p0[axis];
            e1[axis][lane] = e1v[axis];
            e2[axis][lane] = e2v[axis];
        }
        id[lane] = primitiveId;
    }

    template <class Lanes>
    using RayOf = RayLanesOf<Lanes>;  // the ray as it is

    template <class Lanes, class Load>
    [[gnu::always_inline]] static LaneTest<typename Lanes::Type> test(const Load& load, const RayLanesOf<Lanes>& ray,
                                                                      const typename Lanes::Type& limit) {
        return mollerTrumboreLanes<Lanes, TriangleBlock>(load, ray, limit);
    }
};

template <>
struct LeafBlockOf<Triangle> {
    using type = TriangleBlock;
};

}  // namespace rt
