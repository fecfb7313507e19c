// Packet traversal of the KD and BSP trees (Wald 2004, "Realtime Ray Tracing and Interactive
// Global Illumination", 7.1): up to kPacketSize rays that point into the same octant walk the
// tree together. At each node every active ray decides as the single-ray traversal
// (split_tree.cpp) decides; the packet descends while they agree, takes both children when
// they diverge, and carries a mask of the rays still inside the node. One node fetch and one
// branch serve all of them.
//
// Bit for bit the single-ray answer, by construction:
// - Each ray computes its own plane distance with the same operations and gets the same
//   intervals; a ray that would visit only one child is inactive in the other.
// - Rays with one direction sign per axis take both children in the same order (the near one
//   is the one the ray's origin lies in, so the one its direction sign names), so each ray sees
//   its leaves in the order the single traversal sees them.
// - In a leaf each primitive of a kind with blocks is tested against all rays at once (a lane is a
//   ray) with its block's test (geometry/leaf_block.h), the single traversal's, in leaf order, then
//   the other primitives ray by ray. The tie rule is therefore the
//   single traversal's: a hit replaces the nearest only when strictly nearer, so of equally near
//   hits the first found wins, in the first leaf along the ray and, in a leaf, the first primitive.
// - A ray leaves the packet when its nearest hit lies before the node taken from the stack,
//   where the single traversal stops.
// - With a hit filter (cut-outs, single-sided surfaces: geometry/hit_filter.h) a ray's hit is
//   asked of the filter with the ray and the Hit the single traversal asks it with, when that
//   traversal would ask (a hit nearer than the ray's nearest, or before its tMax), and counts only
//   if accepted: the same nearest hits, the same blockers, the same work counted.
// Shadow rays (SplitTree::occludedPacket) walk the same way, each with its own tMax, and a ray
// stops where SplitTree::occluded stops: its lane turns off after the first block of a leaf in
// which one of its primitives lies in (0, tMax), or the first other primitive that does, and its
// tLimit drops to -infinity, so no node left on the stack is open to it any more. Until then it
// counts, node by node and block by block, what the single ray counts.
// A ray left alone in a node, the others having gone elsewhere or ended, goes on from there with
// the single traversal (SplitTree::searchNearest and searchBlocker, the same code the single
// queries run): the same nodes, tests and counts, without the packet's work for its idle lanes.
// Rays that do not share an octant, or have a direction component that is zero or whose
// reciprocal overflows (their plane distances can be NaN, and the single traversal then orders
// the children by the origin), are traced one by one. With the
// watertight triangle test (geometry/watertight_triangle.h) a triangle is tested against the rays
// sheared, each with its own shear, so they must also share the axis they run most along (the
// rays of a camera tile nearly always do); else they too are traced one by one.
//
// Compiled three times (accel/simd_level.h): on SSE2 lanes (core/simd.h, simd_base), on AVX2 lanes
// in namespace simd_avx2 and on AVX-512 lanes in simd_avx512. SplitTree::intersectPacket and
// occludedPacket (simd_dispatch.cpp) choose one at run time; a lone ray goes on with the single
// traversal of the same level (kd_single.cpp).
#include <algorithm>
#include <bit>
#include <cmath>
#include <type_traits>

#include "accel/split_tree.h"
#include "geometry/watertight_triangle.h"

// Last, in a block of its own (clang-format sorts a block): the level's region starts in it
// (accel/simd_level.h), with the leaves' loops and the packet's lanes.
#include "accel/leaf_tests.h"
#include "accel/packet_lanes.h"

namespace rt::RT_LEVEL_NAMESPACE {

namespace {

// The rays' per-axis data, and the interval of each inside a node with the rays inside it. For the
// watertight test also each ray's shear (ShearedRay), along the axes all of them share.
struct PacketRays {
    Lanes origin[3], direction[3], inverse[3];
    Lanes sx, sy, sz;
    ShearedRay axes;
};

struct Span {
    Lanes active, tMin, tMax;
};

// A packet as the traversal takes it: its rays, the part of each inside the root voxel (inactive
// where it misses the voxel), the distance each ends at, and the octant they share.
struct Packet {
    PacketRays rays;
    Span root;
    Lanes tMax;
    bool belowIsNear[3];  // per axis: the rays move up it
};

// Loads rays[0, count), rays[i] ending at tMax[i], into `packet`; lanes past `count` repeat ray 0
// and stay inactive. False, and `packet` unusable, if the rays are not coherent: finite origins,
// one octant, every direction component nonzero with a finite reciprocal (see the note at the top),
// and, `sheared` (for the watertight test), the same axes of their shears.
bool loadPacket(const Ray* rays, int count, const Real* tMax, const Aabb& bounds, bool sheared, Packet& packet) {
    alignas(64) Real values[15][kPacketSize];  // origin, direction, inverse (xyz each), tMin, tEnd, tMax, shear
    LaneBits inside = 0;
    for (int i = 0; i < kPacketSize; ++i) {
        const int r = i < count ? i : 0;
        const Ray& ray = rays[r];
        const Vec3 invDir = reciprocal(ray.direction);
        for (int axis = 0; axis < 3; ++axis)
            if (!std::isfinite(invDir[axis]) || !std::isfinite(ray.origin[axis]) ||
                (ray.direction[axis] > 0) != (rays[0].direction[axis] > 0))
                return false;
        Real tMin = 0, tEnd = tMax[r];
        if (i < count && clipRay(bounds, ray, invDir, tMin, tEnd)) inside |= 1u << i;
        for (int axis = 0; axis < 3; ++axis) {
            values[axis][i] = ray.origin[axis];
            values[3 + axis][i] = ray.direction[axis];
            values[6 + axis][i] = invDir[axis];
        }
        values[9][i] = tMin;
        values[10][i] = tEnd;
        values[11][i] = tMax[r];
        if (sheared) {
            const ShearedRay shear(ray);
            if (i == 0) packet.rays.axes = shear;
            const ShearedRay& first = packet.rays.axes;
            if (shear.kx != first.kx || shear.ky != first.ky || shear.kz != first.kz) return false;
            values[12][i] = shear.sx;
            values[13][i] = shear.sy;
            values[14][i] = shear.sz;
        }
    }
    if (sheared) {
        packet.rays.sx = load(values[12]);
        packet.rays.sy = load(values[13]);
        packet.rays.sz = load(values[14]);
    }
    for (int axis = 0; axis < 3; ++axis) {
        packet.rays.origin[axis] = load(values[axis]);
        packet.rays.direction[axis] = load(values[3 + axis]);
        packet.rays.inverse[axis] = load(values[6 + axis]);
        packet.belowIsNear[axis] = rays[0].direction[axis] > 0;
    }
    packet.root = {maskOf(inside), load(values[9]), load(values[10])};
    packet.tMax = load(values[11]);
    return true;
}

// The nearest hit of each ray so far.
struct PacketHits {
    Lanes t, u, v;
    std::uint32_t prim[kPacketSize];
};

// The level's lanes as a block test takes them (geometry/leaf_block.h).
struct LevelLanes {
    using Type = RealLanes;
    static constexpr int kWidth = kLanes;
    static RealLanes all(Real x) { return broadcast(x); }
    static RealLanes load(const Real* p) { return loadLanes(p); }
};

// What one group of rays meets of a primitive: the rays that hit it with 0 < t < their limit, and
// t, u and v (of every ray).
using GroupHits = LaneTest<RealLanes>;

// Group g of the packet's rays, a ray per lane, as Block's test takes them (Block::RayOf): sheared
// for the watertight test's VertexBlocks (each ray by its own shear, along the axes they share),
// else as they are.
template <class Block>
[[gnu::always_inline]] inline typename Block::template RayOf<LevelLanes> groupRays(const PacketRays& rays, int g) {
    if constexpr (std::is_same_v<Block, VertexBlock>) {
        const int kx = rays.axes.kx, ky = rays.axes.ky, kz = rays.axes.kz;
        return ShearedRayLanesOf<LevelLanes>(
            {rays.origin[kx].group[g], rays.origin[ky].group[g], rays.origin[kz].group[g]}, rays.sx.group[g],
            rays.sy.group[g], rays.sz.group[g], rays.axes);
    } else {
        RayLanesOf<LevelLanes> group;
        for (int axis = 0; axis < 3; ++axis) {
            group.origin[axis] = rays.origin[axis].group[g];
            group.direction[axis] = rays.direction[axis].group[g];
        }
        return group;
    }
}

// Which hits count, as the packet asks it of its rays: every hit (AllHits), or those the scene's
// hit filter accepts (FilteredHits, geometry/hit_filter.h). The traversals are compiled for each,
// so that a tree without a filter runs the loops it ran before filters came to packets. Each has:
// keep(g, hit, hits, id): group g's lanes `hit`, whose hits on primitive `id` are `hits`, less those
// that do not count; nearest(prims, id, r, hit): primitive `id`'s hit of ray r, nearer than `hit`
// and counting, into `hit`; occludes(prims, id, r, tMax): whether it blocks ray r before tMax.
struct AllHits {
    const Ray* rays;  // the packet's, ray i in lane i

    RealLanes keep(int, RealLanes hit, const GroupHits&, std::uint32_t) const { return hit; }
    void nearest(const PrimitiveView& prims, std::uint32_t id, int r, Hit& hit) const {
        prims.intersect(id, rays[r], hit.t, hit);
    }
    bool occludes(const PrimitiveView& prims, std::uint32_t id, int r, Real tMax) const {
        return prims.intersectsAny(id, rays[r], tMax);
    }
};

// The filter is asked ray by ray, with the ray and the Hit that intersect() and occluded() ask it with.
struct FilteredHits {
    const Ray* rays;
    const HitFilter& filter;

    RealLanes keep(int g, RealLanes hit, const GroupHits& hits, std::uint32_t id) const {
        const LaneBits bits = laneBits(hit);
        if (bits == 0) return hit;
        alignas(64) Real t[kLanes], u[kLanes], v[kLanes];
        storeLanes(t, hits.t);
        storeLanes(u, hits.u);
        storeLanes(v, hits.v);
        LaneBits kept = bits;
        for (LaneBits lanes = bits; lanes != 0; lanes &= lanes - 1) {
            const int lane = std::countr_zero(lanes);
            if (!filter.accepts(rays[g * kLanes + lane], {t[lane], id, u[lane], v[lane]})) kept &= ~(1u << lane);
        }
        return kept == bits ? hit : groupMaskOf(kept);
    }
    void nearest(const PrimitiveView& prims, std::uint32_t id, int r, Hit& hit) const {
        intersectFiltered(prims, id, rays[r], filter, hit);
    }
    bool occludes(const PrimitiveView& prims, std::uint32_t id, int r, Real tMax) const {
        return occludesFiltered(prims, id, rays[r], tMax, filter);
    }
};

// Primitive `lane` of a block against group g of the packet's rays: the block's test
// (geometry/leaf_block.h) with the primitive in every lane and a ray per lane, so each ray gets
// the bits its single traversal gets. Both queries test primitives with it: the nearest hit with
// the ray's nearest so far as `limit`, the any hit with its tMax.
template <class Block>
[[gnu::always_inline]] inline GroupHits hitLane(const Block& block, int lane, const PacketRays& rays, int g,
                                                const RealLanes& limit) {
    return Block::template test<LevelLanes>([&](auto row) { return broadcast(row(block)[lane]); },
                                            groupRays<Block>(rays, g), limit);
}

// Primitive `id`'s hits on the `active` rays are taken where they are nearer than the ray's
// nearest and the filter accepts them, as the single traversal takes its hits in order;
// hitGroup(g, limit) tests it against group g of the rays.
template <class Counting, typename HitGroup>
inline void takeNearer(std::uint32_t id, const Lanes& active, const Counting& counting, PacketHits& nearest,
                       const HitGroup& hitGroup) {
    LaneBits taken = 0;
    for (int g = 0; g < kGroups; ++g) {
        const GroupHits h = hitGroup(g, nearest.t.group[g]);
        const RealLanes hit = counting.keep(g, active.group[g] & h.hit, h, id);
        const LaneBits bits = laneBits(hit);
        if (bits == 0) continue;
        nearest.t.group[g] = select(hit, h.t, nearest.t.group[g]);
        nearest.u.group[g] = select(hit, h.u, nearest.u.group[g]);
        nearest.v.group[g] = select(hit, h.v, nearest.v.group[g]);
        taken |= bits << (g * kLanes);
    }
    for (LaneBits bits = taken; bits != 0; bits &= bits - 1) nearest.prim[std::countr_zero(bits)] = id;
}

// Primitive `lane` of a block against the packet's nearest hits.
template <class Block, class Counting>
inline void nearestIn(const Block& block, int lane, const PacketRays& rays, const Lanes& active,
                      const Counting& counting, PacketHits& nearest) {
    takeNearer(block.id[lane], active, counting, nearest,
               [&](int g, RealLanes limit) { return hitLane(block, lane, rays, g, limit); });
}

// Adds to `blocked` the rays of `open` that primitive `lane` of the block hits before their tLimit,
// where the filter accepts the hit.
template <class Block, class Counting>
inline void blockingIn(const Block& block, int lane, const PacketRays& rays, const Lanes& open, const Lanes& tLimit,
                       const Counting& counting, Lanes& blocked) {
    for (int g = 0; g < kGroups; ++g) {
        const GroupHits h = hitLane(block, lane, rays, g, tLimit.group[g]);
        blocked.group[g] = blocked.group[g] | counting.keep(g, open.group[g] & h.hit, h, block.id[lane]);
    }
}

// The single traversal's decision at a node, ray by ray (split_tree.cpp, SplitTree::traverse),
// mapped to the packet's near and far child; `belowIsNear`: the rays move up the axis. A ray
// takes its first child alone when the plane lies beyond its interval or behind its origin, its
// second alone when the plane lies before the interval, else both, split at the plane. Its first
// child is the side of its origin, or for an origin on the plane the side it moves into; when it
// takes both that is the near child (the plane lies ahead). Only the near child's tMax and the
// far child's tMin change, and only for the rays that take both.
struct Descent {
    Lanes nearRays, farRays, nearTMax, farTMin;
};

inline void descend(const PacketRays& rays, const Span& span, int axis, Real split, bool belowIsNear, Descent& out) {
    const RealLanes plane = broadcast(split), zero = broadcast(0);
    for (int g = 0; g < kGroups; ++g) {
        const RealLanes origin = rays.origin[axis].group[g];
        const RealLanes tMin = span.tMin.group[g], tMax = span.tMax.group[g], active = span.active.group[g];
        const RealLanes tPlane = (plane - origin) * rays.inverse[axis].group[g];
        const RealLanes firstOnly = lessThan(tMax, tPlane) | lessEqual(tPlane, zero);
        const RealLanes secondOnly = andNot(firstOnly, lessThan(tPlane, tMin));
        const RealLanes both = andNot(firstOnly | secondOnly, active);
        const RealLanes firstIsNear = belowIsNear ? lessThan(origin, plane) : lessThan(plane, origin);
        out.nearRays.group[g] = both | (active & ((firstOnly & firstIsNear) | andNot(firstIsNear, secondOnly)));
        out.farRays.group[g] = both | (active & (andNot(firstIsNear, firstOnly) | (secondOnly & firstIsNear)));
        out.nearTMax.group[g] = select(both, tPlane, tMax);
        out.farTMin.group[g] = select(both, tPlane, tMin);
    }
}

// The rays of `span` for which something may still lie in its node, their tLimit not before it:
// where the single traversal goes on.
Lanes stillOpen(const Span& span, const Lanes& tLimit) {
    Lanes open;
    for (int g = 0; g < kGroups; ++g)
        open.group[g] = andNot(lessThan(tLimit.group[g], span.tMin.group[g]), span.active.group[g]);
    return open;
}

// The packet's walk through the tree's `nodes`, both queries': front to back, each ray visiting
// the nodes its single traversal visits, in its order. visitLeaf(unit, inLeaf, active) is called
// at each non-empty leaf with its primitiveOffset() and the rays in it (lanes and bits); it may
// lower `tLimit`, per ray the distance from which on nothing is sought: the nearest hit so far,
// or -infinity for a shadow ray found blocked. Returns the nodes visited, once per ray.
// A ray left alone in a node is handed on: searchAlone(ray, node, tMin, tMax) searches the node's
// subtree with the single traversal (SplitTree::searchNearest or searchBlocker), which visits and
// counts there what the packet would, at a fraction of a packet's work per node and triangle
// (the rays of a packet part after a few levels in scenes of many small triangles), and lowers the
// ray's tLimit as a leaf would.
template <typename VisitLeaf, typename SearchAlone>
std::uint64_t walk(const SplitNode* nodes, const Packet& packet, const Lanes& tLimit, const VisitLeaf& visitLeaf,
                   const SearchAlone& searchAlone) {
    struct Pending {
        std::uint32_t node;
        Span span;
    };
    Pending stack[kMaxTreeDepth];
    int size = 0;
    std::uint32_t index = 0;
    std::uint64_t steps = 0;
    Span span = packet.root;
    LaneBits active = bitsOf(span.active);
    while (active != 0) {
        SplitNode node = nodes[index];
        while (!node.isLeaf() && !std::has_single_bit(active)) {
            steps += std::uint64_t(std::popcount(active));
            const int axis = node.axis();
            const bool belowIsNear = packet.belowIsNear[axis];
            Descent d;
            descend(packet.rays, span, axis, Real(node.split()), belowIsNear, d);
            const LaneBits nearRays = bitsOf(d.nearRays);
            const std::uint32_t nearChild = belowIsNear ? index + 1 : node.aboveChild();
            const std::uint32_t farChild = belowIsNear ? node.aboveChild() : index + 1;
            if (nearRays == 0) {  // no ray takes both: only the mask changes
                index = farChild;
                span.active = d.farRays;
                active = bitsOf(d.farRays);
            } else {
                if (bitsOf(d.farRays) != 0) stack[size++] = {farChild, {d.farRays, d.farTMin, span.tMax}};
                index = nearChild;
                span.active = d.nearRays;
                span.tMax = d.nearTMax;
                active = nearRays;
            }
            node = nodes[index];
        }
        if (std::has_single_bit(active)) {
            const int ray = std::countr_zero(active);
            searchAlone(ray, index, laneOf(span.tMin, ray), laneOf(span.tMax, ray));
        } else {
            steps += std::uint64_t(std::popcount(active));
            if (node.primitiveCount() != 0) visitLeaf(node.primitiveOffset(), span.active, active);
        }
        // The next node with a ray for which something may still lie in it.
        active = 0;
        while (active == 0 && size > 0) {
            const Pending& next = stack[--size];
            index = next.node;
            span = next.span;
            span.active = stillOpen(span, tLimit);
            active = bitsOf(span.active);
        }
    }
    return steps;
}

// Lets update(ray, hit) change the nearest hit of each ray of `rays` as a Hit, ray by ray: the
// hits leave the lanes once and go back once.
template <typename Update>
void updateHits(PacketHits& nearest, LaneBits rays, const Update& update) {
    alignas(64) Real t[kPacketSize], u[kPacketSize], v[kPacketSize];
    store(nearest.t, t);
    store(nearest.u, u);
    store(nearest.v, v);
    for (LaneBits bits = rays; bits != 0; bits &= bits - 1) {
        const int r = std::countr_zero(bits);
        Hit hit{t[r], nearest.prim[r], u[r], v[r]};
        update(r, hit);
        t[r] = hit.t;
        nearest.prim[r] = hit.prim;
        u[r] = hit.u;
        v[r] = hit.v;
    }
    nearest.t = load(t);
    nearest.u = load(u);
    nearest.v = load(v);
}

// The leaf's primitives of kinds without blocks, ray by ray, as the single traversal tests them.
template <class Counting>
void nearestOthers(const PrimitiveView& prims, const LeafPrimitives& leaf, const Counting& counting, LaneBits active,
                   PacketHits& nearest) {
    updateHits(nearest, active, [&](int r, Hit& hit) {
        for (std::uint32_t i = 0; i < leaf.others; ++i) counting.nearest(prims, leaf.otherIds()[i], r, hit);
    });
}

// The rays of `active` (lanes `open`) that one of `blocks` (holding `total` primitives of a
// kind) blocks before their tLimit, block by block, a block's kSimdWidth (fewer in the last)
// tested and counted together, a ray stopping after the first block that blocks it. Updates `open`
// and `active`.
template <class Block, class Counting>
LaneBits blockedInBlocks(const Block* blocks, std::uint32_t blockCount, std::uint32_t total, const PacketRays& packet,
                         const Counting& counting, Lanes& open, LaneBits& active, const Lanes& tLimit,
                         std::uint64_t& tests) {
    LaneBits blocked = 0;
    for (std::uint32_t b = 0; b < blockCount && active != 0; ++b) {
        const std::uint32_t size = std::min<std::uint32_t>(kSimdWidth, total - b * kSimdWidth);
        tests += std::uint64_t(std::popcount(active)) * size;
        Lanes hit = broadcastLanes(0);
        for (std::uint32_t lane = 0; lane < size; ++lane)
            blockingIn(blocks[b], int(lane), packet, open, tLimit, counting, hit);
        for (int g = 0; g < kGroups; ++g) open.group[g] = andNot(hit.group[g], open.group[g]);
        blocked |= bitsOf(hit);
        active &= ~blocked;
    }
    return blocked;
}

// The rays of `active` (lanes `open`) that something in `leaf` blocks before their tLimit (their
// tMax), found and counted as SplitTree::occluded finds and counts them ray by ray: the blocks of
// each kind with blocks block by block, kind after kind (blockedInBlocks), then the other
// primitives one at a time, until one blocks (a hit the filter accepts). The triangles by the test
// `test`.
template <TriangleTest test, class Counting>
LaneBits blockedInLeaf(const PrimitiveView& prims, const LeafPrimitives& leaf, const Counting& counting,
                       const Real* tMax, const PacketRays& packet, Lanes open, LaneBits active, const Lanes& tLimit,
                       std::uint64_t& tests) {
    LaneBits blocked = 0;
    anyBlockKind([&](auto kind) {
        blocked |= blockedInBlocks(leaf.blocks<test, kind>(), leaf.blockCount<kind>(), leaf.blocked[kind], packet,
                                   counting, open, active, tLimit, tests);
        return false;
    });
    for (LaneBits bits = active; bits != 0; bits &= bits - 1) {
        const int r = std::countr_zero(bits);
        for (std::uint32_t i = 0; i < leaf.others; ++i) {
            ++tests;
            if (counting.occludes(prims, leaf.otherIds()[i], r, tMax[r])) {
                blocked |= 1u << r;
                break;
            }
        }
    }
    return blocked;
}

// Takes the rays of `bits` out of the search: no node's interval starts before -infinity.
void closeRays(LaneBits bits, Lanes& tLimit) {
    const Lanes closed = maskOf(bits);
    for (int g = 0; g < kGroups; ++g) tLimit.group[g] = select(closed.group[g], broadcast(-kInfinity), tLimit.group[g]);
}

}  // namespace

}  // namespace rt::RT_LEVEL_NAMESPACE

namespace rt {

template <SimdLevel level, TriangleTest test>
void SplitTree::tracePacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found,
                            RayCounters& counters) const {
    using namespace RT_LEVEL_LANES;
    static_assert(level == RT_LEVEL, "each compilation of this file holds its own level's traversal");
    Real ends[kPacketSize];
    std::fill(std::begin(ends), std::end(ends), tMax);
    Packet packet;
    if (!tracesTogether(count) || !loadPacket(rays, count, ends, bounds_, test == TriangleTest::Watertight, packet)) {
        Accelerator::intersectPacket(rays, count, tMax, hits, found, counters);
        return;
    }
    PacketHits nearest{};
    nearest.t = packet.tMax;
    std::uint64_t tests = 0;
    const PrimitiveView prims = view_;
    // The walk, for the hits that count (AllHits or FilteredHits).
    const auto search = [&](const auto& counting) {
        return walk(
            nodes_.data(), packet, nearest.t,
            [&](std::uint32_t unit, const Lanes& inLeaf, LaneBits active) {
                const LeafPrimitives& leaf = leafAt(unit);
                tests += std::uint64_t(std::popcount(active)) * leaf.count();
                // As SplitTree::intersect: each kind with blocks in leaf order, kind after kind, then the others.
                anyBlockKind([&](auto kind) {
                    for (std::uint32_t k = 0; k < leaf.blocked[kind]; ++k)
                        nearestIn(leaf.blocks<test, kind>()[k / kSimdWidth], int(k % kSimdWidth), packet.rays, inLeaf,
                                  counting, nearest);
                    return false;
                });
                if (leaf.others != 0) nearestOthers(prims, leaf, counting, active, nearest);
            },
            [&](int ray, std::uint32_t node, Real tMin, Real tEnd) {
                updateHits(nearest, 1u << ray, [&](int r, Hit& hit) {
                    searchNearest<level, test>(rays[r], reciprocal(rays[r].direction), node, tMin, tEnd, hit, counters);
                });
            });
    };
    counters.traversalSteps += filter_ ? search(FilteredHits{rays, *filter_}) : search(AllHits{rays});
    counters.intersectionTests += tests;
    alignas(64) Real t[kPacketSize], u[kPacketSize], v[kPacketSize];
    store(nearest.t, t);
    store(nearest.u, u);
    store(nearest.v, v);
    for (int i = 0; i < count; ++i) {
        found[i] = t[i] < tMax;
        if (found[i]) hits[i] = {t[i], nearest.prim[i], u[i], v[i]};
    }
}

template <SimdLevel level, TriangleTest test>
void SplitTree::traceShadowPacket(const Ray* rays, int count, const Real* tMax, bool* blocked,
                                  RayCounters& counters) const {
    using namespace RT_LEVEL_LANES;
    static_assert(level == RT_LEVEL, "each compilation of this file holds its own level's traversal");
    Packet packet;
    if (!tracesTogether(count) || !loadPacket(rays, count, tMax, bounds_, test == TriangleTest::Watertight, packet)) {
        Accelerator::occludedPacket(rays, count, tMax, blocked, counters);
        return;
    }
    Lanes tLimit = packet.tMax;
    LaneBits found = 0;
    std::uint64_t tests = 0;
    const PrimitiveView prims = view_;
    const auto search = [&](const auto& counting) {
        return walk(
            nodes_.data(), packet, tLimit,
            [&](std::uint32_t unit, const Lanes& inLeaf, LaneBits active) {
                const LaneBits now = blockedInLeaf<test>(prims, leafAt(unit), counting, tMax, packet.rays, inLeaf,
                                                         active, tLimit, tests);
                found |= now;
                if (now != 0) closeRays(now, tLimit);  // where SplitTree::occluded stops
            },
            [&](int ray, std::uint32_t node, Real tMin, Real tEnd) {
                if (!searchBlocker<level, test>(rays[ray], reciprocal(rays[ray].direction), node, tMin, tEnd, tMax[ray],
                                                counters))
                    return;
                found |= 1u << ray;
                closeRays(1u << ray, tLimit);
            });
    };
    counters.traversalSteps += filter_ ? search(FilteredHits{rays, *filter_}) : search(AllHits{rays});
    counters.intersectionTests += tests;
    for (int i = 0; i < count; ++i) blocked[i] = (found >> i) & 1u;
}

template void SplitTree::tracePacket<RT_LEVEL, TriangleTest::MollerTrumbore>(const Ray*, int, Real, Hit*, bool*,
                                                                             RayCounters&) const;
template void SplitTree::tracePacket<RT_LEVEL, TriangleTest::Watertight>(const Ray*, int, Real, Hit*, bool*,
                                                                         RayCounters&) const;
template void SplitTree::traceShadowPacket<RT_LEVEL, TriangleTest::MollerTrumbore>(const Ray*, int, const Real*, bool*,
                                                                                   RayCounters&) const;
template void SplitTree::traceShadowPacket<RT_LEVEL, TriangleTest::Watertight>(const Ray*, int, const Real*, bool*,
                                                                               RayCounters&) const;

}  // namespace rt

RT_LEVEL_END
