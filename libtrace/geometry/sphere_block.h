// Spheres laid out for the trees' leaves, as triangle_block.h lays out triangles: kSimdWidth at a
// time, each as its centre and squared radius, component by component, in the order the leaves
// list them, so a leaf's spheres are read from consecutive memory and tested together. The lanes
// compute exactly what intersectSphere (sphere.h) computes, operation by operation, so a block's
// hits have the scalar test's bits.
#pragma once

#include <algorithm>
#include <cstdint>
#include <iterator>

#include "geometry/sphere.h"
#include "geometry/triangle_block.h"

namespace rt {

struct alignas(16) SphereBlock {
    static constexpr std::uint32_t kNoPrimitive = ~0u;  // an unused lane: radius 0 and far away, never hit
    Real center[3][kSimdWidth] = {};
    Real r2[kSimdWidth] = {};  // radius * radius, as intersectSphere squares it
    std::uint32_t id[kSimdWidth];

    SphereBlock() {
        std::fill(std::begin(id), std::end(id), kNoPrimitive);
        // A point sphere at infinity: l2 and d2 are infinite or NaN, which no hit condition passes.
        for (auto& axis : center) std::fill(std::begin(axis), std::end(axis), kInfinity);
    }

    void set(int lane, const Sphere& s, std::uint32_t primitiveId) {
        for (int axis = 0; axis < 3; ++axis) center[axis][lane] = s.center[axis];
        r2[lane] = s.radius * s.radius;
        id[lane] = primitiveId;
    }
};

// intersectSphere with one sphere per lane: the same operations in the same order, its rejections
// as masks. load(member, axis) gives the lanes' SphereBlock::center on one axis, or (axis -1) r2.
// The hits' u and v are 0, as intersect(Sphere) sets them. Always inlined, as
// mollerTrumboreLanes is.
template <class Lanes, int N, class Load>
[[gnu::always_inline]] inline LaneHits<N> sphereLanes(const Load& load, const RayLanesOf<Lanes>& ray, Real tMax) {
    using L = typename Lanes::Type;
    const L zero = Lanes::all(0);
    const L &dx = ray.direction[0], &dy = ray.direction[1], &dz = ray.direction[2];
    const L lx = load(0) - ray.origin[0], ly = load(1) - ray.origin[1], lz = load(2) - ray.origin[2];
    const L tca = lx * dx + ly * dy + lz * dz;
    const L l2 = lx * lx + ly * ly + lz * lz;
    const L r2 = load(-1);
    const L outside = lessThan(r2, l2);
    const L d2 = l2 - tca * tca;
    const L missed = (outside & lessThan(tca, zero)) | lessThan(r2, d2);
    const L thc = squareRoot(r2 - d2);
    const L near = select(outside, tca - thc, tca + thc);
    const L t = select(lessThan(zero, near), near, tca + thc);  // the origin on the surface: the far side
    return LaneHits<N>::of(andNot(missed, lessThan(zero, t) & lessThan(t, Lanes::all(tMax))), t, zero, zero);
}

// The test on one block's spheres.
inline BlockHits intersectBlock(const SphereBlock& b, const RayLanes& ray, Real tMax) {
    return sphereLanes<BaseLanes, kSimdWidth>([&](int axis) { return loadLanes(axis < 0 ? b.r2 : b.center[axis]); },
                                              ray, tMax);
}

}  // namespace rt
