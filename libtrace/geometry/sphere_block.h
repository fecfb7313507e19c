// Spheres laid out for the trees' leaves, the spheres' block (geometry/leaf_block.h), as
// triangle_block.h lays out triangles: kSimdWidth at a time, each as its centre and squared radius,
// component by component. The lanes compute exactly what intersectSphere (sphere.h) computes,
// operation by operation, so a block's hits have the scalar test's bits.
#pragma once

#include <algorithm>
#include <cstdint>
#include <iterator>

#include "geometry/leaf_block.h"
#include "geometry/sphere.h"

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

    // intersectSphere with one sphere per lane: the same operations in the same order, its
    // rejections as masks. The hits' u and v are 0, as intersect(Sphere) sets them.
    template <class Lanes>
    using RayOf = RayLanesOf<Lanes>;  // the ray as it is

    template <class Lanes, class Load>
    [[gnu::always_inline]] static LaneTest<typename Lanes::Type> test(const Load& load, const RayLanesOf<Lanes>& ray,
                                                                      const typename Lanes::Type& limit) {
        using L = typename Lanes::Type;
        const L zero = Lanes::all(0);
        const L &dx = ray.direction[0], &dy = ray.direction[1], &dz = ray.direction[2];
        const L lx = load(blockRow<SphereBlock>(&SphereBlock::center, 0)) - ray.origin[0],
                ly = load(blockRow<SphereBlock>(&SphereBlock::center, 1)) - ray.origin[1],
                lz = load(blockRow<SphereBlock>(&SphereBlock::center, 2)) - ray.origin[2];
        const L tca = lx * dx + ly * dy + lz * dz;
        const L l2 = lx * lx + ly * ly + lz * lz;
        const L r2 = load([](const SphereBlock& b) -> const Real* { return b.r2; });
        const L outside = lessThan(r2, l2);
        const L d2 = l2 - tca * tca;
        const L missed = (outside & lessThan(tca, zero)) | lessThan(r2, d2);
        const L thc = squareRoot(r2 - d2);
        const L near = select(outside, tca - thc, tca + thc);
        LaneTest<L> hits;
        hits.t = select(lessThan(zero, near), near, tca + thc);  // the origin on the surface: the far side
        hits.u = hits.v = zero;
        hits.hit = andNot(missed, lessThan(zero, hits.t) & lessThan(hits.t, limit));
        return hits;
    }
};

template <>
struct LeafBlockOf<Sphere> {
    using type = SphereBlock;
};

}  // namespace rt
