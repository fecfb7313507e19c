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

// The ray, once per ray in every lane.
struct RayLanes {
    RealLanes origin[3], direction[3];
    explicit RayLanes(const Ray& ray) {
        for (int axis = 0; axis < 3; ++axis) {
            origin[axis] = broadcast(ray.origin[axis]);
            direction[axis] = broadcast(ray.direction[axis]);
        }
    }
};

// One lane per triangle of the hits with 0 < t < tMax, as intersectTriangle decides them.
struct BlockHits {
    unsigned lanes = 0;  // bit i: lane i hits
    Real t[kSimdWidth], u[kSimdWidth], v[kSimdWidth];
};

// Moller-Trumbore on a block's triangles (see intersectTriangle: the same operations in the same
// order; every lane is computed, the rejections become masks).
inline BlockHits intersectBlock(const TriangleBlock& b, const RayLanes& ray, Real tMax) {
    const auto load = [](const Real(&c)[3][kSimdWidth], int axis) { return loadLanes(c[axis]); };
    const RealLanes e1x = load(b.e1, 0), e1y = load(b.e1, 1), e1z = load(b.e1, 2);
    const RealLanes e2x = load(b.e2, 0), e2y = load(b.e2, 1), e2z = load(b.e2, 2);
    const RealLanes &dx = ray.direction[0], &dy = ray.direction[1], &dz = ray.direction[2];
    // p = cross(d, e2), det = dot(e1, p)
    const RealLanes px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
    const RealLanes det = e1x * px + e1y * py + e1z * pz;
    const RealLanes invDet = broadcast(1) / det;
    // s = origin - p0, u = dot(s, p) / det
    const RealLanes sx = ray.origin[0] - load(b.p0, 0), sy = ray.origin[1] - load(b.p0, 1),
                    sz = ray.origin[2] - load(b.p0, 2);
    const RealLanes u = (sx * px + sy * py + sz * pz) * invDet;
    // q = cross(s, e1), v = dot(d, q) / det, t = dot(e2, q) / det
    const RealLanes qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
    const RealLanes v = (dx * qx + dy * qy + dz * qz) * invDet;
    const RealLanes t = (e2x * qx + e2y * qy + e2z * qz) * invDet;
    const RealLanes zero = broadcast(0), one = broadcast(1);
    const RealLanes inside = notEqual(det, zero) & notLessThan(u, zero) & notGreaterThan(u, one) &
                             notLessThan(v, zero) & notGreaterThan(u + v, one);
    BlockHits hits;
    hits.lanes = laneBits(inside & lessThan(zero, t) & lessThan(t, broadcast(tMax)));
    if (hits.lanes) {
        storeLanes(hits.t, t);
        storeLanes(hits.u, u);
        storeLanes(hits.v, v);
    }
    return hits;
}

}  // namespace rt
