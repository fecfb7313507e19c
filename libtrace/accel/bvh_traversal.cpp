// The BVH's single-ray queries (Bvh::intersect, occluded): a node's eight children tested at once
// by slabs on the level's lanes (one register of eight floats on AVX2 and AVX-512, two on SSE2;
// doubles in one to four), the children hit pushed on a stack, for the nearest hit the nearest
// child last so that it is taken first. Compiled three times, as the trees' traversals are
// (accel/simd_level.h); Bvh::intersect and occluded choose the copy at run time.
#include <bit>
#include <cmath>
#include <cstdint>

#include "accel/bvh_tree.h"

// Last, in a block of its own: the level's region starts in it (accel/simd_level.h).
#include "accel/leaf_tests.h"

namespace rt::RT_LEVEL_NAMESPACE {

namespace {

// The slack (kBvhSlackUlps, accel/bvh_tree.h): how far along the ray a child's box is taken to
// reach beyond its computed slab interval, on both ends, and so beyond the nearest hit so far too: a primitive's
// computed hit is rounded in its position by some units in the last place of the ray's origin and of the scene's
// coordinates (a triangle's test subtracts its vertex from the origin), and may lie outside the
// box of its primitive by that much, more than the builder's padding (accel/bvh_build.cpp, in
// the scene's units only) when the origin lies far from the scene. A child that rounding would
// cull although its primitive reports a nearer hit is then entered, so that the nearest hit is
// the one every primitive's test would give. AccelPathological.AllPrimitivesAtOnePoint (float)
// shoots rays from a unit away at tiny triangles and spheres: a triangle's hit comes out at t = 1
// although the scene's padded box, which holds them all, is entered at 1.0000021 (18 ulps of 1),
// and the spheres' child, entered there, was culled, while a sphere's test (its discriminant
// cancels) reports a hit nearer still: 16 is the least slack that passes, 64 leaves room. It
// covers the slab distances' own rounding too (a subtraction and a product, a few ulps of t,
// which for a box in the scene is within the two magnitudes' sum):
// pbrt-v4's 1 + 2 gamma(3), Ize 2013.

// The ray as the slab tests read it: per axis, its origin and reciprocal direction in every lane,
// and which of a node's planes it meets first (the lower when it runs towards higher values); and
// its slack (slabSlack), for a scene whose largest coordinate has magnitude `sceneMagnitude`.
struct SlabRay {
    RealLanes origin[3], inverse[3];
    int nearIsHigh[3];
    Real slack;

    SlabRay(const Ray& ray, Real sceneMagnitude) : slack(slabSlack(ray, sceneMagnitude)) {
        const Vec3 inv = reciprocal(ray.direction);
        for (int axis = 0; axis < 3; ++axis) {
            origin[axis] = broadcast(ray.origin[axis]);
            inverse[axis] = broadcast(inv[axis]);
            // -0 counts as downward: its reciprocal is -inf, and so the high plane comes first.
            nearIsHigh[axis] = std::signbit(ray.direction[axis]) ? 1 : 0;
        }
    }
};

// The children of `node` whose boxes the ray enters before `tLimit` (bit i for slot i), both
// widened by the ray's slack, and where it enters each (tNear[i], at least 0). A lane where the
// origin lies on a plane it runs parallel to computes 0 * inf = NaN, which maximum and minimum
// pass over (their second operand is taken): the ray then counts as inside that slab. An unused
// slot's box, +inf to -inf, is never entered.
[[gnu::always_inline]] inline unsigned childrenHit(const BvhNode& node, const SlabRay& ray, Real tLimit,
                                                   Real (&tNear)[kBvhWidth]) {
    const RealLanes zero = broadcast(0), limit = broadcast(tLimit), slack = broadcast(ray.slack);
    unsigned bits = 0;
    for (int first = 0; first < kBvhWidth; first += kLanes) {
        RealLanes entry = zero, exit = limit;
        for (int axis = 0; axis < 3; ++axis) {
            const Real* nearPlanes = ray.nearIsHigh[axis] ? node.hi[axis] : node.lo[axis];
            const Real* farPlanes = ray.nearIsHigh[axis] ? node.lo[axis] : node.hi[axis];
            entry = maximum((loadLanes(nearPlanes + first) - ray.origin[axis]) * ray.inverse[axis], entry);
            exit = minimum((loadLanes(farPlanes + first) - ray.origin[axis]) * ray.inverse[axis], exit);
        }
        storeLanes(tNear + first, entry);
        bits |= laneBits(lessEqual(entry, exit + slack)) << first;
    }
    return bits;
}

// A child waiting on the stack, and where the ray enters it.
struct Pending {
    BvhChild child;
    Real tNear;
};
// The most children waiting at once: all but the one taken of each level, and the root.
constexpr int kStackSize = (kBvhWidth - 1) * kMaxBvhDepth + 1;

// Pushes the children `bits` of `node`, for the nearest hit the nearest last (popped first): an
// insertion sort of the few pushed, which keeps slot order between equal distances.
[[gnu::always_inline]] inline void pushNearestLast(const BvhNode& node, unsigned bits, const Real (&tNear)[kBvhWidth],
                                                   Pending* stack, int& size) {
    const int first = size;
    for (; bits != 0; bits &= bits - 1) {
        const int slot = std::countr_zero(bits);
        const Pending entry{node.child[slot], tNear[slot]};
        int at = size++;
        for (; at > first && stack[at - 1].tNear < entry.tNear; --at) stack[at] = stack[at - 1];
        stack[at] = entry;
    }
}

}  // namespace

}  // namespace rt::RT_LEVEL_NAMESPACE

namespace rt {

// Nearest first, down the nearest child hit, the others waiting on the stack nearest on top; a
// child is taken from the stack only if it starts before the nearest hit so far (with the ray's
// slack), which a leaf's tests (accel/leaf_tests.h) lower. A node with one child hit hands it on
// without the stack.
template <SimdLevel level, TriangleTest test, bool noteTies>
void Bvh::searchNearest(const Ray& ray, BvhChild start, Hit& nearest, RayCounters& counters, bool* tied) const {
    using namespace RT_LEVEL_LANES;
    static_assert(level == RT_LEVEL, "each compilation of this file holds its own level's traversal");
    const SlabRay slabs(ray, sceneMagnitude_);
    const BlockTests<test> testBlocks(ray);
    const HitFilter* filter = filter_;
    const PrimitiveView prims = view_;  // a local copy, kept in registers (see PrimitiveView)
    std::uint64_t steps = 0, tests = 0;
    Pending stack[kStackSize];
    int size = 0;
    Real tNear[kBvhWidth];
    BvhChild current = start;
    for (;;) {
        ++steps;
        if (current.isLeaf()) {
            nearestInLeaf<test, noteTies>(testBlocks, prims, leaves_.at(current.index()), ray, filter, nearest, tests,
                                          tied);
        } else {
            const BvhNode& node = nodes_[current.index()];
            const unsigned bits = childrenHit(node, slabs, nearest.t, tNear);
            if (bits != 0 && (bits & (bits - 1)) == 0) {
                current = node.child[std::countr_zero(bits)];
                continue;
            }
            pushNearestLast(node, bits, tNear, stack, size);
        }
        while (size != 0 && stack[size - 1].tNear > nearest.t + slabs.slack) --size;
        if (size == 0) break;
        current = stack[--size].child;
    }
    counters.traversalSteps += steps;
    counters.intersectionTests += tests;
}

// Any hit, as Embree's occluded1: no order by distance (any blocker ends the search), the last
// child hit taken at once and the others pushed in slot order, so that the next popped is the
// one before it; the search ends at the first leaf that blocks. The child taken goes on in a
// register rather than through the stack.
template <SimdLevel level, TriangleTest test>
bool Bvh::searchBlocker(const Ray& ray, BvhChild start, Real tMax, RayCounters& counters) const {
    using namespace RT_LEVEL_LANES;
    static_assert(level == RT_LEVEL, "each compilation of this file holds its own level's traversal");
    const SlabRay slabs(ray, sceneMagnitude_);
    const BlockTests<test> testBlocks(ray);
    const HitFilter* filter = filter_;
    const PrimitiveView prims = view_;
    std::uint64_t steps = 0, tests = 0;
    BvhChild stack[kStackSize];
    int size = 0;
    Real tNear[kBvhWidth];
    bool blocked = false;
    BvhChild current = start;
    for (;;) {
        ++steps;
        if (current.isLeaf()) {
            blocked = blockerInLeaf(testBlocks, prims, leaves_.at(current.index()), ray, tMax, filter, tests);
            if (blocked) break;
        } else {
            const BvhNode& node = nodes_[current.index()];
            unsigned bits = childrenHit(node, slabs, tMax, tNear);
            if (bits != 0) {
                for (; (bits & (bits - 1)) != 0; bits &= bits - 1) stack[size++] = node.child[std::countr_zero(bits)];
                current = node.child[std::countr_zero(bits)];
                continue;
            }
        }
        if (size == 0) break;
        current = stack[--size];
    }
    counters.traversalSteps += steps;
    counters.intersectionTests += tests;
    return blocked;
}

template void Bvh::searchNearest<RT_LEVEL, TriangleTest::MollerTrumbore, false>(const Ray&, BvhChild, Hit&,
                                                                                RayCounters&, bool*) const;
template void Bvh::searchNearest<RT_LEVEL, TriangleTest::Watertight, false>(const Ray&, BvhChild, Hit&, RayCounters&,
                                                                            bool*) const;
template void Bvh::searchNearest<RT_LEVEL, TriangleTest::MollerTrumbore, true>(const Ray&, BvhChild, Hit&, RayCounters&,
                                                                               bool*) const;
template void Bvh::searchNearest<RT_LEVEL, TriangleTest::Watertight, true>(const Ray&, BvhChild, Hit&, RayCounters&,
                                                                           bool*) const;
template bool Bvh::searchBlocker<RT_LEVEL, TriangleTest::MollerTrumbore>(const Ray&, BvhChild, Real,
                                                                         RayCounters&) const;
template bool Bvh::searchBlocker<RT_LEVEL, TriangleTest::Watertight>(const Ray&, BvhChild, Real, RayCounters&) const;

}  // namespace rt

RT_LEVEL_END
