// Packet traversal of the wide BVH (Wald, Benthin, Wagner and Slusallek 2001; Embree's packet
// traversal of its BVH8): up to kPacketSize rays that point into one octant walk the nodes
// together. At a node each of its children is slab-tested against all the packet's rays at once,
// a ray per lane, with the single traversal's operations (accel/bvh_traversal.cpp, childrenHit)
// in its order, so that each ray enters exactly the children it enters alone against the same
// nearest hit; the packet goes down the child nearest along its first ray, the others wait on the
// stack with the mask of their rays and where each enters. A ray leaves a waiting child when its
// nearest hit is found before the child's entry (for the any-hit query, when it is blocked). One
// fetch of a node and one walk of the stack serve all the rays.
//
// A leaf is tested ray by ray with the single traversal's loops (accel/leaf_tests.h), hit filter
// included, so each ray gets from it what it gets alone; a ray left alone in a node, or one of two
// (kFewRays), goes on there by itself with the single traversal (Bvh::searchNearest and searchBlocker, the code the
// single queries run), without the packet's work for idle lanes.
//
// Bit for bit the single-ray answer. Any hit: a ray is blocked if one of the leaves it enters
// holds a blocker; it enters the same leaves as alone (the same tests against the same tMax), in
// another order, and only stops early. Nearest hit: the ray meets the leaves its box tests let
// through in the packet's order rather than its own, and enters every leaf whose box starts
// before its nearest hit (with the slack), as alone, so it finds the same nearest t; only which
// of two equally near hits it keeps can differ, since the tie rule keeps the first found
// (docs/trees.md). So its leaves note hits exactly as near as its nearest (nearestInLeaf's
// `noteTies`), and a ray that met one is traced again alone: rare (a ray through an edge shared by
// two triangles at the same t), and exact.
//
// Rays that do not share an octant (the sign bits of their directions) are traced one by one, as
// are packets of one ray. Compiled three times (accel/simd_level.h); Bvh::intersectPacket and
// occludedPacket (bvh_tree.cpp) choose the copy at run time.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include "accel/bvh_tree.h"

// Last, in a block of its own (clang-format sorts a block): the level's region starts in it
// (accel/simd_level.h), with the leaves' loops and the packet's lanes.
#include "accel/leaf_tests.h"
#include "accel/packet_lanes.h"

namespace rt::RT_LEVEL_NAMESPACE {

namespace {

// The packet's rays as the slab tests read them: per axis each ray's origin and reciprocal
// direction, a ray per lane, and which of a node's planes they all meet first; each ray's slack
// (slabSlack).
struct SlabPacket {
    Lanes origin[3], inverse[3], slack;
    int nearIsHigh[3];
};

// Loads rays[0, count) into `packet`, the lanes past `count` repeating ray 0. False, and `packet`
// unusable, if the rays do not share an octant: the sign bits of their directions, which decide
// which plane comes first (-0 counts as downward, as in the single traversal).
bool loadSlabPacket(const Ray* rays, int count, Real sceneMagnitude, SlabPacket& packet) {
    alignas(64) Real values[7][kPacketSize];  // origin, inverse (xyz each), slack
    for (int axis = 0; axis < 3; ++axis) packet.nearIsHigh[axis] = std::signbit(rays[0].direction[axis]) ? 1 : 0;
    for (int i = 0; i < kPacketSize; ++i) {
        const Ray& ray = rays[i < count ? i : 0];
        const Vec3 inverse = reciprocal(ray.direction);
        for (int axis = 0; axis < 3; ++axis) {
            if ((std::signbit(ray.direction[axis]) ? 1 : 0) != packet.nearIsHigh[axis]) return false;
            values[axis][i] = ray.origin[axis];
            values[3 + axis][i] = inverse[axis];
        }
        values[6][i] = slabSlack(ray, sceneMagnitude);
    }
    for (int axis = 0; axis < 3; ++axis) {
        packet.origin[axis] = load(values[axis]);
        packet.inverse[axis] = load(values[3 + axis]);
    }
    packet.slack = load(values[6]);
    return true;
}

// The rays that enter child `slot` of `node` before their tLimit, both widened by each ray's
// slack, and where each enters (`entry`, at least 0): the single traversal's test (childrenHit),
// the same operations in the same order with the child's planes in every lane and a ray per lane.
[[gnu::always_inline]] inline LaneBits raysInChild(const BvhNode& node, int slot, const SlabPacket& packet,
                                                   const Lanes& tLimit, Lanes& entry) {
    RealLanes nearPlane[3], farPlane[3];
    for (int axis = 0; axis < 3; ++axis) {
        const bool highFirst = packet.nearIsHigh[axis] != 0;
        nearPlane[axis] = broadcast(highFirst ? node.hi[axis][slot] : node.lo[axis][slot]);
        farPlane[axis] = broadcast(highFirst ? node.lo[axis][slot] : node.hi[axis][slot]);
    }
    LaneBits bits = 0;
    for (int g = 0; g < kGroups; ++g) {
        RealLanes in = broadcast(0), out = tLimit.group[g];
        for (int axis = 0; axis < 3; ++axis) {
            const RealLanes origin = packet.origin[axis].group[g], inverse = packet.inverse[axis].group[g];
            in = maximum((nearPlane[axis] - origin) * inverse, in);
            out = minimum((farPlane[axis] - origin) * inverse, out);
        }
        entry.group[g] = in;
        bits |= laneBits(lessEqual(in, out + packet.slack.group[g])) << (g * kLanes);
    }
    return bits;
}

// The most rays left in a node that go on from there one by one with the single traversal: the
// packet tests a child against all its lanes whatever their number, the single traversal tests
// all eight children against one ray in one register's work, so a few rays go faster alone. Two,
// by bench/vs_embree on all nine scenes (docs/benchmarks.md, "The BVH's shadow rays"): for shadow
// packets one was within the noise of it; three was slower on five scenes of nine (the packet's
// nodes are shared fetches, and each ray handed on sets up the single traversal again), and so was
// handing every ray on where the rays part (no child entered by more than half of them) on eight.
constexpr int kFewRays = 2;

// A child waiting on the stack: the rays that enter it and where each does.
struct PendingRays {
    BvhChild child;
    LaneBits rays;
    Lanes entry;
};
// The most children waiting at once: all but the one taken of each level, and the root.
constexpr int kStackSize = (kBvhWidth - 1) * kMaxBvhDepth + 1;

// Pushes the children of `node` that rays of `active` enter, the child nearest along the packet's
// first active ray last; returns how many it pushed. An insertion sort of the few pushed, which
// keeps slot order between equal distances.
[[gnu::always_inline]] inline int pushNearestLast(const BvhNode& node, const SlabPacket& packet, const Lanes& tLimit,
                                                  LaneBits active, PendingRays* stack, int& size) {
    const int first = size, leader = std::countr_zero(active);
    Real key[kBvhWidth];  // the leader's entry of each child pushed, by its place among them
    for (std::uint32_t slot = 0; slot < node.children; ++slot) {
        PendingRays entry;
        entry.rays = raysInChild(node, int(slot), packet, tLimit, entry.entry) & active;
        if (entry.rays == 0) continue;
        entry.child = node.child[slot];
        const Real distance = laneOf(entry.entry, leader);
        int at = size++;
        for (; at > first && key[at - 1 - first] < distance; --at) {
            stack[at] = stack[at - 1];
            key[at - first] = key[at - 1 - first];
        }
        stack[at] = entry;
        key[at - first] = distance;
    }
    return size - first;
}

// The rays of `rays` for which the child `pending` may still hold a nearer hit: those whose entry
// is at most their nearest hit so far plus their slack, where the single traversal takes it too.
[[gnu::always_inline]] inline LaneBits stillOpen(const PendingRays& pending, const SlabPacket& packet,
                                                 const Lanes& tLimit) {
    LaneBits open = 0;
    for (int g = 0; g < kGroups; ++g)
        open |= laneBits(lessEqual(pending.entry.group[g], tLimit.group[g] + packet.slack.group[g])) << (g * kLanes);
    return pending.rays & open;
}

// The leaves' tests of each of the packet's rays (BlockTests: the ray on the lanes the leaves'
// blocks are tested on), made once per packet.
template <TriangleTest test>
struct RayBlockTests {
    std::optional<BlockTests<test>> ray[kPacketSize];

    RayBlockTests(const Ray* rays, int count) {
        for (int i = 0; i < count; ++i) ray[i].emplace(rays[i]);
    }
};

}  // namespace

}  // namespace rt::RT_LEVEL_NAMESPACE

namespace rt {

template <SimdLevel level, TriangleTest test>
void Bvh::tracePacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found, RayCounters& counters) const {
    using namespace RT_LEVEL_LANES;
    static_assert(level == RT_LEVEL, "each compilation of this file holds its own level's traversal");
    SlabPacket packet;
    if (count <= 1 || nodes_.empty() || !loadSlabPacket(rays, count, sceneMagnitude_, packet)) {
        Accelerator::intersectPacket(rays, count, tMax, hits, found, counters);
        return;
    }
    const RayBlockTests<test> blockTests(rays, count);
    const HitFilter* filter = filter_;
    const PrimitiveView prims = view_;
    Hit nearest[kPacketSize];
    bool tied[kPacketSize] = {};
    alignas(64) Real limits[kPacketSize];  // each ray's nearest t so far
    for (int i = 0; i < kPacketSize; ++i) nearest[i].t = limits[i] = tMax;
    Lanes tLimit = load(limits);
    std::uint64_t steps = 0, tests = 0;
    PendingRays stack[kStackSize];
    int size = 0;
    BvhChild current = BvhChild::inner(0);
    LaneBits active = (1u << count) - 1;
    for (;;) {
        if (std::popcount(active) <= kFewRays) {
            for (LaneBits bits = active; bits != 0; bits &= bits - 1) {
                const int r = std::countr_zero(bits);
                searchNearest<level, test, true>(rays[r], current, nearest[r], counters, &tied[r]);
                limits[r] = nearest[r].t;
            }
            tLimit = load(limits);
        } else if (current.isLeaf()) {
            steps += std::uint64_t(std::popcount(active));
            const LeafPrimitives& leaf = leaves_.at(current.index());
            for (LaneBits bits = active; bits != 0; bits &= bits - 1) {
                const int r = std::countr_zero(bits);
                nearestInLeaf<test, true>(*blockTests.ray[r], prims, leaf, rays[r], filter, nearest[r], tests,
                                          &tied[r]);
                limits[r] = nearest[r].t;
            }
            tLimit = load(limits);
        } else {
            steps += std::uint64_t(std::popcount(active));
            if (pushNearestLast(nodes_[current.index()], packet, tLimit, active, stack, size) != 0) {
                const PendingRays& nearestChild = stack[--size];  // entered by its rays before their nearest hit
                current = nearestChild.child;
                active = nearestChild.rays;
                continue;
            }
        }
        active = 0;
        while (active == 0 && size != 0) {
            const PendingRays& next = stack[--size];
            active = stillOpen(next, packet, tLimit);
            current = next.child;
        }
        if (active == 0) break;
    }
    counters.traversalSteps += steps;
    counters.intersectionTests += tests;
    for (int i = 0; i < count; ++i) {
        if (tied[i]) {  // another order could keep another of its equally near hits: its own order decides
            nearest[i] = Hit{};
            nearest[i].t = tMax;
            searchNearest<level, test>(rays[i], BvhChild::inner(0), nearest[i], counters);
        }
        found[i] = nearest[i].t < tMax;
        if (found[i]) hits[i] = nearest[i];
    }
}

template <SimdLevel level, TriangleTest test>
void Bvh::traceShadowPacket(const Ray* rays, int count, const Real* tMax, bool* blocked, RayCounters& counters) const {
    using namespace RT_LEVEL_LANES;
    static_assert(level == RT_LEVEL, "each compilation of this file holds its own level's traversal");
    SlabPacket packet;
    if (count <= 1 || nodes_.empty() || !loadSlabPacket(rays, count, sceneMagnitude_, packet)) {
        Accelerator::occludedPacket(rays, count, tMax, blocked, counters);
        return;
    }
    const RayBlockTests<test> blockTests(rays, count);
    const HitFilter* filter = filter_;
    const PrimitiveView prims = view_;
    alignas(64) Real limits[kPacketSize];
    for (int i = 0; i < kPacketSize; ++i) limits[i] = tMax[i < count ? i : 0];
    const Lanes tLimit = load(limits);
    const LaneBits all = (1u << count) - 1;
    LaneBits done = 0;  // the rays found blocked
    std::uint64_t steps = 0, tests = 0;
    // As Bvh::occluded: the children in slot order, the last pushed taken first.
    struct Pending {
        BvhChild child;
        LaneBits rays;
    };
    Pending stack[kStackSize];
    int size = 0;
    stack[size++] = {BvhChild::inner(0), all};
    while (size != 0 && done != all) {
        const Pending next = stack[--size];
        const LaneBits active = next.rays & ~done;
        if (active == 0) continue;
        if (std::popcount(active) <= kFewRays) {
            for (LaneBits bits = active; bits != 0; bits &= bits - 1) {
                const int r = std::countr_zero(bits);
                if (searchBlocker<level, test>(rays[r], next.child, tMax[r], counters)) done |= 1u << r;
            }
            continue;
        }
        steps += std::uint64_t(std::popcount(active));
        if (next.child.isLeaf()) {
            const LeafPrimitives& leaf = leaves_.at(next.child.index());
            for (LaneBits bits = active; bits != 0; bits &= bits - 1) {
                const int r = std::countr_zero(bits);
                if (blockerInLeaf(*blockTests.ray[r], prims, leaf, rays[r], tMax[r], filter, tests)) done |= 1u << r;
            }
            continue;
        }
        const BvhNode& node = nodes_[next.child.index()];
        for (std::uint32_t slot = 0; slot < node.children; ++slot) {
            Lanes entry;
            const LaneBits entering = raysInChild(node, int(slot), packet, tLimit, entry) & active;
            if (entering != 0) stack[size++] = {node.child[slot], entering};
        }
    }
    counters.traversalSteps += steps;
    counters.intersectionTests += tests;
    for (int i = 0; i < count; ++i) blocked[i] = (done >> i) & 1u;
}

template void Bvh::tracePacket<RT_LEVEL, TriangleTest::MollerTrumbore>(const Ray*, int, Real, Hit*, bool*,
                                                                       RayCounters&) const;
template void Bvh::tracePacket<RT_LEVEL, TriangleTest::Watertight>(const Ray*, int, Real, Hit*, bool*,
                                                                   RayCounters&) const;
template void Bvh::traceShadowPacket<RT_LEVEL, TriangleTest::MollerTrumbore>(const Ray*, int, const Real*, bool*,
                                                                             RayCounters&) const;
template void Bvh::traceShadowPacket<RT_LEVEL, TriangleTest::Watertight>(const Ray*, int, const Real*, bool*,
                                                                         RayCounters&) const;

}  // namespace rt

RT_LEVEL_END
