// Triangles laid out for the trees' leaves (issue 14): kSimdWidth at a time (core/simd.h), each as a vertex and
// its two edges (the Moller-Trumbore form), component by component, in the order the leaves
// list them, so a leaf's triangles are read from consecutive memory and tested together
// (core/simd.h). The lanes compute exactly what intersectTriangle (triangle.h) computes,
// operation by operation, so a block's hits have the scalar test's bits.
#pragma once

#include <algorithm>
#include <cstdint>
#include <iterator>

#include "core/simd.h"
#include "geometry/triangle.h"

namespace rt {

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
};

// A set of lanes the block test runs on: Type, a register of Real lanes with core/simd.h's
// operations (found by argument-dependent lookup), all(x), x in every lane, and load(p), the lanes
// from p (aligned to 64 bytes). BaseLanes is
// simd_base's register, one block's width; accel/kd_single.cpp adds a register two blocks wide.
struct BaseLanes {
    using Type = RealLanes;
    static RealLanes all(Real x) { return broadcast(x); }
    static RealLanes load(const Real* p) { return loadLanes(p); }
};

// The ray, once per ray in every lane.
template <class Lanes>
struct RayLanesOf {
    typename Lanes::Type origin[3], direction[3];
    // Always inlined, as the block test (mollerTrumboreLanes) is.
    [[gnu::always_inline]] explicit RayLanesOf(const Ray& ray) {
        for (int axis = 0; axis < 3; ++axis) {
            origin[axis] = Lanes::all(ray.origin[axis]);
            direction[axis] = Lanes::all(ray.direction[axis]);
        }
    }
};
using RayLanes = RayLanesOf<BaseLanes>;

// One lane per triangle of the hits with 0 < t < tMax, as intersectTriangle decides them.
template <int N>
struct LaneHits {
    unsigned lanes = 0;  // bit i: lane i hits
    Real t[N], u[N], v[N];

    // The hits of the lanes set in `hit`, their t, u and v stored only if there are any.
    template <class L>
    [[gnu::always_inline]] static LaneHits of(const L& hit, const L& t, const L& u, const L& v) {
        LaneHits hits;
        hits.lanes = laneBits(hit);
        if (hits.lanes) {
            storeLanes(hits.t, t);
            storeLanes(hits.u, u);
            storeLanes(hits.v, v);
        }
        return hits;
    }
};
using BlockHits = LaneHits<kSimdWidth>;

// Moller-Trumbore with one triangle per lane (see intersectTriangle: the same operations in the
// same order; every lane is computed, the rejections become masks). load(component, axis) gives
// the lanes' triangles' TriangleBlock::p0, e1 or e2 (a pointer to the member) on one axis. Always
// inlined: in a function compiled for AVX2 or AVX-512 (core/simd.h) the test is compiled for it too.
template <class Lanes, int N, class Load>
[[gnu::always_inline]] inline LaneHits<N> mollerTrumboreLanes(const Load& load, const RayLanesOf<Lanes>& ray,
                                                              Real tMax) {
    using L = typename Lanes::Type;
    const L e1x = load(&TriangleBlock::e1, 0), e1y = load(&TriangleBlock::e1, 1), e1z = load(&TriangleBlock::e1, 2);
    const L e2x = load(&TriangleBlock::e2, 0), e2y = load(&TriangleBlock::e2, 1), e2z = load(&TriangleBlock::e2, 2);
    const L &dx = ray.direction[0], &dy = ray.direction[1], &dz = ray.direction[2];
    // p = cross(d, e2), det = dot(e1, p)
    const L px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
    const L det = e1x * px + e1y * py + e1z * pz;
    const L invDet = Lanes::all(1) / det;
    // s = origin - p0, u = dot(s, p) / det
    const L sx = ray.origin[0] - load(&TriangleBlock::p0, 0), sy = ray.origin[1] - load(&TriangleBlock::p0, 1),
            sz = ray.origin[2] - load(&TriangleBlock::p0, 2);
    const L u = (sx * px + sy * py + sz * pz) * invDet;
    // q = cross(s, e1), v = dot(d, q) / det, t = dot(e2, q) / det
    const L qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
    const L v = (dx * qx + dy * qy + dz * qz) * invDet;
    const L t = (e2x * qx + e2y * qy + e2z * qz) * invDet;
    const L zero = Lanes::all(0), one = Lanes::all(1);
    const L inside = notEqual(det, zero) & notLessThan(u, zero) & notGreaterThan(u, one) & notLessThan(v, zero) &
                     notGreaterThan(u + v, one);
    return LaneHits<N>::of(inside & lessThan(zero, t) & lessThan(t, Lanes::all(tMax)), t, u, v);
}

// The test on one block's triangles.
inline BlockHits intersectBlock(const TriangleBlock& b, const RayLanes& ray, Real tMax) {
    return mollerTrumboreLanes<BaseLanes, kSimdWidth>(
        [&](auto component, int axis) { return loadLanes((b.*component)[axis]); }, ray, tMax);
}

}  // namespace rt
