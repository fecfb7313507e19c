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
// - In a leaf each triangle is tested against all rays at once (a lane is a ray), with the
//   operations of the single traversal's block test (geometry/triangle_block.h) in its order,
//   triangles in leaf order, then the other primitives ray by ray. The tie rule is therefore the
//   single traversal's: a hit replaces the nearest only when strictly nearer, so of equally near
//   hits the first found wins, in the first leaf along the ray and, in a leaf, the first primitive.
// - A ray leaves the packet when its nearest hit lies before the node taken from the stack,
//   where the single traversal stops.
// Rays that do not share an octant, have a direction component that is zero or whose
// reciprocal overflows (their plane distances can be NaN, and the single traversal then orders
// the children by the origin), and a tree with a hit filter are traced one by one.
//
// Compiled three times (libtrace/CMakeLists.txt): as it is, on SSE2 lanes (core/simd.h,
// simd_base); with RT_PACKET_AVX2 defined, on AVX2 lanes: the same code in namespace simd_avx2,
// its functions compiled for AVX2; with RT_PACKET_AVX512, the same on AVX-512 lanes in
// simd_avx512. SplitTree::intersectPacket (packet_dispatch.cpp) chooses one at run time. The
// headers are included before the AVX2 or AVX-512 region, so the inline functions they define,
// which other files share, keep the baseline instructions.
#include <bit>
#include <cmath>

#include "accel/split_tree.h"

#if RT_PACKET_AVX2
#if !RT_SIMD_AVX2
#error "RT_PACKET_AVX2 needs core/simd.h's AVX2 lanes (x86-64, GCC or clang)"
#endif
#define RT_PACKET_LANES simd_avx2
#define RT_PACKET_LEVEL SimdLevel::avx2
#define RT_PACKET_NAMESPACE simd_avx2
RT_AVX2_BEGIN
#elif RT_PACKET_AVX512
#if !RT_SIMD_AVX512
#error "RT_PACKET_AVX512 needs core/simd.h's AVX-512 lanes (x86-64, GCC or clang)"
#endif
#define RT_PACKET_LANES simd_avx512
#define RT_PACKET_LEVEL SimdLevel::avx512
#define RT_PACKET_NAMESPACE simd_avx512
RT_AVX512_BEGIN
#else
#define RT_PACKET_LANES simd_base
#define RT_PACKET_LEVEL SimdLevel::sse2
#define RT_PACKET_NAMESPACE inline simd_base  // reopened as what core/simd.h declares it
#endif

namespace rt::RT_PACKET_NAMESPACE {

namespace {

// The packet in groups of one register's lanes (core/simd.h): SSE2 takes four groups of two
// doubles or two of four floats, AVX2 two of four doubles or one of eight floats, AVX-512 one of
// eight doubles or eight floats.
constexpr int kGroups = kPacketSize / kLanes;
static_assert(kGroups * kLanes == kPacketSize);

// Masks are all-ones lanes (core/simd.h); bit i of a LaneBits is ray i.
using LaneBits = unsigned;

struct Lanes {
    RealLanes group[kGroups];
};

LaneBits bitsOf(const Lanes& mask) {
    LaneBits bits = 0;
    for (int g = 0; g < kGroups; ++g) bits |= laneBits(mask.group[g]) << (g * kLanes);
    return bits;
}

// A lane mask from one flag per ray.
Lanes maskOf(const bool (&set)[kPacketSize]) {
    alignas(64) Real lanes[kPacketSize];
    for (int i = 0; i < kPacketSize; ++i) lanes[i] = set[i] ? Real(1) : Real(0);
    Lanes mask;
    for (int g = 0; g < kGroups; ++g) mask.group[g] = notEqual(loadLanes(lanes + g * kLanes), broadcast(0));
    return mask;
}

Lanes load(const Real (&values)[kPacketSize]) {
    Lanes l;
    for (int g = 0; g < kGroups; ++g) l.group[g] = loadLanes(values + g * kLanes);
    return l;
}

Lanes broadcastLanes(Real value) {
    Lanes l;
    for (int g = 0; g < kGroups; ++g) l.group[g] = broadcast(value);
    return l;
}

void store(const Lanes& l, Real (&values)[kPacketSize]) {
    for (int g = 0; g < kGroups; ++g) storeLanes(values + g * kLanes, l.group[g]);
}

// The rays' per-axis data, and the interval of each inside a node with the rays inside it.
struct PacketRays {
    Lanes origin[3], direction[3], inverse[3];
};

// The nearest hit of each ray so far.
struct PacketHits {
    Lanes t, u, v;
    std::uint32_t prim[kPacketSize];
};

// Moller-Trumbore of one triangle of a block against every ray of the packet: intersectBlock's
// operations in its order, lane by lane (a lane is a ray here, not a triangle), so each ray gets
// the bits its single traversal gets. A hit is taken where it is nearer than the ray's nearest,
// as the single traversal takes a block's hits in order.
inline void nearestTriangle(const TriangleBlock& block, int lane, const PacketRays& rays, const Lanes& active,
                            PacketHits& nearest) {
    const RealLanes e1x = broadcast(block.e1[0][lane]), e1y = broadcast(block.e1[1][lane]),
                    e1z = broadcast(block.e1[2][lane]);
    const RealLanes e2x = broadcast(block.e2[0][lane]), e2y = broadcast(block.e2[1][lane]),
                    e2z = broadcast(block.e2[2][lane]);
    const RealLanes p0x = broadcast(block.p0[0][lane]), p0y = broadcast(block.p0[1][lane]),
                    p0z = broadcast(block.p0[2][lane]);
    const RealLanes zero = broadcast(0), one = broadcast(1);
    LaneBits taken = 0;
    for (int g = 0; g < kGroups; ++g) {
        const RealLanes dx = rays.direction[0].group[g], dy = rays.direction[1].group[g],
                        dz = rays.direction[2].group[g];
        const RealLanes px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
        const RealLanes det = e1x * px + e1y * py + e1z * pz;
        const RealLanes invDet = one / det;
        const RealLanes sx = rays.origin[0].group[g] - p0x, sy = rays.origin[1].group[g] - p0y,
                        sz = rays.origin[2].group[g] - p0z;
        const RealLanes u = (sx * px + sy * py + sz * pz) * invDet;
        const RealLanes qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
        const RealLanes v = (dx * qx + dy * qy + dz * qz) * invDet;
        const RealLanes t = (e2x * qx + e2y * qy + e2z * qz) * invDet;
        const RealLanes inside = notEqual(det, zero) & notLessThan(u, zero) & notGreaterThan(u, one) &
                                 notLessThan(v, zero) & notGreaterThan(u + v, one);
        const RealLanes hit = active.group[g] & inside & lessThan(zero, t) & lessThan(t, nearest.t.group[g]);
        const LaneBits bits = laneBits(hit);
        if (bits == 0) continue;
        nearest.t.group[g] = select(hit, t, nearest.t.group[g]);
        nearest.u.group[g] = select(hit, u, nearest.u.group[g]);
        nearest.v.group[g] = select(hit, v, nearest.v.group[g]);
        taken |= bits << (g * kLanes);
    }
    for (LaneBits bits = taken; bits != 0; bits &= bits - 1) nearest.prim[std::countr_zero(bits)] = block.id[lane];
}

struct Span {
    Lanes active, tMin, tMax;
};

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

// The rays of `span` whose nearest hit so far may still lie in its node: where the single
// traversal goes on.
Lanes stillOpen(const Span& span, const Lanes& nearestT) {
    Lanes open;
    for (int g = 0; g < kGroups; ++g)
        open.group[g] = andNot(lessThan(nearestT.group[g], span.tMin.group[g]), span.active.group[g]);
    return open;
}

// The leaf's primitives that are not triangles, ray by ray (the packet has no hit filter).
void nearestOthers(const PrimitiveView& prims, const LeafPrimitives& leaf, const Ray* rays, LaneBits active,
                   PacketHits& nearest) {
    alignas(64) Real t[kPacketSize], u[kPacketSize], v[kPacketSize];
    store(nearest.t, t);
    store(nearest.u, u);
    store(nearest.v, v);
    for (LaneBits bits = active; bits != 0; bits &= bits - 1) {
        const int r = std::countr_zero(bits);
        Hit hit{t[r], nearest.prim[r], u[r], v[r]};
        for (std::uint32_t i = 0; i < leaf.others; ++i) prims.intersect(leaf.otherIds()[i], rays[r], hit.t, hit);
        t[r] = hit.t;
        nearest.prim[r] = hit.prim;
        u[r] = hit.u;
        v[r] = hit.v;
    }
    nearest.t = load(t);
    nearest.u = load(u);
    nearest.v = load(v);
}

}  // namespace

}  // namespace rt::RT_PACKET_NAMESPACE

namespace rt {

template <SimdLevel level>
void SplitTree::tracePacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found,
                            RayCounters& counters) const {
    using namespace RT_PACKET_LANES;
    static_assert(level == RT_PACKET_LEVEL, "each compilation of this file holds its own level's traversal");
    // Lanes past `count` repeat ray 0 and stay inactive.
    alignas(64) Real values[11][kPacketSize];  // origin, direction, inverse (xyz each), tMin, tMax
    bool inside[kPacketSize] = {};
    bool coherent = !filter_ && count >= 2 && !nodes_.empty() && !bounds_.empty();
    for (int i = 0; i < kPacketSize && coherent; ++i) {
        const Ray& ray = rays[i < count ? i : 0];
        const Vec3 invDir = reciprocal(ray.direction);
        // Finite origins, one octant, every direction component nonzero with a finite
        // reciprocal (see the note at the top).
        for (int axis = 0; axis < 3; ++axis)
            coherent = coherent && std::isfinite(invDir[axis]) && std::isfinite(ray.origin[axis]) &&
                       (ray.direction[axis] > 0) == (rays[0].direction[axis] > 0);
        Real tMin = 0, tEnd = tMax;
        inside[i] = i < count && clipRay(bounds_, ray, invDir, tMin, tEnd);
        for (int axis = 0; axis < 3; ++axis) {
            values[axis][i] = ray.origin[axis];
            values[3 + axis][i] = ray.direction[axis];
            values[6 + axis][i] = invDir[axis];
        }
        values[9][i] = tMin;
        values[10][i] = tEnd;
    }
    if (!coherent) {
        Accelerator::intersectPacket(rays, count, tMax, hits, found, counters);
        return;
    }
    PacketRays packet;
    for (int axis = 0; axis < 3; ++axis) {
        packet.origin[axis] = load(values[axis]);
        packet.direction[axis] = load(values[3 + axis]);
        packet.inverse[axis] = load(values[6 + axis]);
    }
    Span span{maskOf(inside), load(values[9]), load(values[10])};
    PacketHits nearest{};
    nearest.t = broadcastLanes(tMax);
    LaneBits active = bitsOf(span.active);
    const bool belowIsNear[3] = {rays[0].direction.x > 0, rays[0].direction.y > 0, rays[0].direction.z > 0};

    struct Pending {
        std::uint32_t node;
        Span span;
    };
    Pending stack[kMaxTreeDepth];
    int size = 0;
    std::uint32_t index = 0;
    std::uint64_t steps = 0, tests = 0;
    const PrimitiveView prims = view_;
    while (active != 0) {
        SplitNode node = nodes_[index];
        while (!node.isLeaf()) {
            steps += std::uint64_t(std::popcount(active));
            const int axis = node.axis();
            Descent d;
            descend(packet, span, axis, Real(node.split()), belowIsNear[axis], d);
            const LaneBits nearRays = bitsOf(d.nearRays);
            const std::uint32_t nearChild = belowIsNear[axis] ? index + 1 : node.aboveChild();
            const std::uint32_t farChild = belowIsNear[axis] ? node.aboveChild() : index + 1;
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
            node = nodes_[index];
        }
        steps += std::uint64_t(std::popcount(active));
        if (node.primitiveCount() != 0) {
            const LeafPrimitives& leaf = leafAt(node.primitiveOffset());
            tests += std::uint64_t(std::popcount(active)) * (leaf.triangles + leaf.others);
            // As SplitTree::nearestInLeaf: the triangles in leaf order, then the other primitives.
            for (std::uint32_t k = 0; k < leaf.triangles; ++k)
                nearestTriangle(leaf.blocks()[k / kSimdWidth], int(k % kSimdWidth), packet, span.active, nearest);
            if (leaf.others != 0) nearestOthers(prims, leaf, rays, active, nearest);
        }
        // The next node with a ray whose nearest hit may still lie in it.
        active = 0;
        while (active == 0 && size > 0) {
            const Pending& next = stack[--size];
            index = next.node;
            span = next.span;
            span.active = stillOpen(span, nearest.t);
            active = bitsOf(span.active);
        }
    }
    counters.traversalSteps += steps;
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

template void SplitTree::tracePacket<RT_PACKET_LEVEL>(const Ray* rays, int count, Real tMax, Hit* hits, bool* found,
                                                      RayCounters& counters) const;

}  // namespace rt

#if RT_PACKET_AVX2
RT_AVX2_END
#elif RT_PACKET_AVX512
RT_AVX512_END
#endif
