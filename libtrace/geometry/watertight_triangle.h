// The watertight ray-triangle test of Woop, Benthin and Wald (JCGT 2(1), 2013), the option
// AccelSettings::triangles = TriangleTest::Watertight (rt-render --watertight; docs/trees.md).
//
// Moller-Trumbore (triangle.h) computes each triangle's barycentric coordinates from its own edges,
// so the two triangles sharing an edge round differently on it and a ray through the edge (or
// through a vertex) can pass between them. This test instead moves the ray's origin to 0 and
// shears space so that the ray runs along +z, projects the three vertices, and asks on which side
// of each projected edge the point (0, 0) lies. A vertex is transformed with the same operations in
// every triangle that shares it, and an edge's 2D cross product computed from the other side is
// exactly its negation, so neighbours agree on the side of their shared edge; a zero, where rounding
// could have hidden the side, is recomputed with its sign exact (exactDifferenceOfProducts). Points
// on an edge count for both triangles. So a closed mesh has no crack: a ray that enters it hits a
// triangle of it.
//
// Blocks (VertexBlock) hold kSimdWidth triangles as their three vertices (the shared vertex must
// be the same value in each of its triangles, which p0 + (p1 - p0) is not), in the bytes a
// TriangleBlock takes, and are tested lane by lane with the scalar test's operations in its order,
// so a block's hits have the scalar test's bits.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>

#include "geometry/triangle.h"
#include "geometry/triangle_block.h"

namespace rt {

// a * b - c * d, its sign and whether it is zero exact (as the test needs, not its last bits). In
// float the products are exact in double and their difference rounds once. In double, Kahan's
// difference of products: the rounding error of c * d, exact through a fused multiply-add, added
// back (within 2 ulps of the exact value, Jeannerod, Louvet and Muller 2013, so never of the wrong
// sign, and zero only when the exact value is).
inline Real exactDifferenceOfProducts(Real a, Real b, Real c, Real d) {
#if defined(RT_REAL_FLOAT)
    return Real(double(a) * double(b) - double(c) * double(d));
#else
    const Real cd = c * d;
    const Real error = std::fma(-c, d, cd);  // cd - c * d, exactly
    return std::fma(a, b, -cd) + error;
#endif
}

// The ray as the test uses it, found once per ray: its axes reordered so that it runs most along
// z (kz, and kx, ky swapped where that axis runs down, which keeps the triangles' winding), and
// the shear that takes its direction to (0, 0, 1): x -= sx z, y -= sy z, z *= sz.
struct ShearedRay {
    Vec3 origin;
    int kx = 0, ky = 1, kz = 2;
    Real sx = 0, sy = 0, sz = 1;

    ShearedRay() = default;  // the ray along +z from 0

    explicit ShearedRay(const Ray& ray) : origin(ray.origin) {
        const Vec3& d = ray.direction;
        kz = std::abs(d.y) > std::abs(d.x) ? 1 : 0;
        if (std::abs(d.z) > std::abs(d[kz])) kz = 2;
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        if (d[kz] < 0) std::swap(kx, ky);
        sx = d[kx] / d[kz];
        sy = d[ky] / d[kz];
        sz = 1 / d[kz];
    }
};

// The edge functions of one triangle, the point (0, 0) against its projected edges (u: the edge
// opposite p0, v: opposite p1, w: opposite p2), recomputed with exact signs when one is zero.
struct EdgeFunctions {
    Real u, v, w;
};

// The projected vertices (ax, ay), (bx, by), (cx, cy) of p0, p1, p2.
inline EdgeFunctions exactEdgeFunctions(Real ax, Real ay, Real bx, Real by, Real cx, Real cy) {
    return {exactDifferenceOfProducts(cx, by, cy, bx), exactDifferenceOfProducts(ax, cy, ay, cx),
            exactDifferenceOfProducts(bx, ay, by, ax)};
}

// The watertight test: a hit with 0 < t < tMax sets t, and u and v, the weights of p1 and p2 (as
// intersectTriangle's), and returns true. A triangle seen edge-on (its projection without area)
// is never hit; its neighbours are.
inline bool intersectWatertight(const Triangle& tri, const ShearedRay& ray, Real tMax, Real& t, Real& u, Real& v) {
    const Vec3 a = tri.p0 - ray.origin, b = tri.p1 - ray.origin, c = tri.p2 - ray.origin;
    const int kx = ray.kx, ky = ray.ky, kz = ray.kz;
    const Real ax = a[kx] - ray.sx * a[kz], ay = a[ky] - ray.sy * a[kz];
    const Real bx = b[kx] - ray.sx * b[kz], by = b[ky] - ray.sy * b[kz];
    const Real cx = c[kx] - ray.sx * c[kz], cy = c[ky] - ray.sy * c[kz];
    EdgeFunctions e{cx * by - cy * bx, ax * cy - ay * cx, bx * ay - by * ax};
    if (e.u == 0 || e.v == 0 || e.w == 0) e = exactEdgeFunctions(ax, ay, bx, by, cx, cy);
    const bool inside = (0 <= e.u && 0 <= e.v && 0 <= e.w) || (e.u <= 0 && e.v <= 0 && e.w <= 0);
    const Real det = e.u + e.v + e.w;
    if (!inside || det == 0) return false;
    // The sheared z of the point, weighted, over det: the distance along the ray.
    const Real scaled = e.u * (ray.sz * a[kz]) + e.v * (ray.sz * b[kz]) + e.w * (ray.sz * c[kz]);
    const Real invDet = 1 / det;
    const Real tt = scaled * invDet;
    if (!(0 < tt && tt < tMax)) return false;
    t = tt;
    u = e.v * invDet;
    v = e.w * invDet;
    return true;
}

inline bool intersectWatertight(const Triangle& tri, const ShearedRay& ray, Real tMax, Hit& hit) {
    return intersectWatertight(tri, ray, tMax, hit.t, hit.u, hit.v);
}

// kSimdWidth triangles as their vertices, component by component, in the bytes of a TriangleBlock.
// An unused lane's vertices are NaN: its edge functions are NaN, and NaN is on no side of an edge.
struct alignas(16) VertexBlock {
    static constexpr std::uint32_t kNoPrimitive = ~0u;
    Real p0[3][kSimdWidth], p1[3][kSimdWidth], p2[3][kSimdWidth];
    std::uint32_t id[kSimdWidth];

    VertexBlock() {
        std::fill(std::begin(id), std::end(id), kNoPrimitive);
        for (Real(*vertex)[kSimdWidth] : {p0, p1, p2})
            for (int axis = 0; axis < 3; ++axis)
                std::fill(std::begin(vertex[axis]), std::end(vertex[axis]), std::numeric_limits<Real>::quiet_NaN());
    }

    void set(int lane, const Triangle& tri, std::uint32_t primitiveId) {
        for (int axis = 0; axis < 3; ++axis) {
            p0[axis][lane] = tri.p0[axis];
            p1[axis][lane] = tri.p1[axis];
            p2[axis][lane] = tri.p2[axis];
        }
        id[lane] = primitiveId;
    }
};
static_assert(sizeof(VertexBlock) == sizeof(TriangleBlock) && alignof(VertexBlock) == alignof(TriangleBlock));

// The sheared ray on lanes: one ray in every lane (the leaves' blocks), or one ray per lane
// (accel/kd_packet.cpp's packets, whose rays share their axes). The axes stay scalars, as they
// choose which rows a block's test loads.
template <class Lanes>
struct ShearedRayLanesOf {
    using L = typename Lanes::Type;
    L origin[3], sx, sy, sz;  // origin in the order kx, ky, kz
    int kx, ky, kz;

    [[gnu::always_inline]] explicit ShearedRayLanesOf(const ShearedRay& ray)
        : ShearedRayLanesOf(
              {Lanes::all(ray.origin[ray.kx]), Lanes::all(ray.origin[ray.ky]), Lanes::all(ray.origin[ray.kz])},
              Lanes::all(ray.sx), Lanes::all(ray.sy), Lanes::all(ray.sz), ray) {}
    // Rays lane by lane, each of them sheared along the axes of `axes`.
    [[gnu::always_inline]] ShearedRayLanesOf(const L (&o)[3], const L& sxLanes, const L& syLanes, const L& szLanes,
                                             const ShearedRay& axes)
        : origin{o[0], o[1], o[2]}, sx(sxLanes), sy(syLanes), sz(szLanes), kx(axes.kx), ky(axes.ky), kz(axes.kz) {}
};
using ShearedRayLanes = ShearedRayLanesOf<BaseLanes>;

// The lanes whose edge function came out zero, recomputed one by one with exact signs, as
// intersectWatertight recomputes them. Rare (a ray through an edge or a vertex, as computed), so
// kept out of the inlined test.
template <int N>
[[gnu::noinline, gnu::cold]] inline void refineEdgeFunctions(unsigned lanes, const Real (&xy)[6][N], Real (&u)[N],
                                                             Real (&v)[N], Real (&w)[N]) {
    for (; lanes != 0; lanes &= lanes - 1) {
        const int i = std::countr_zero(lanes);
        const EdgeFunctions e = exactEdgeFunctions(xy[0][i], xy[1][i], xy[2][i], xy[3][i], xy[4][i], xy[5][i]);
        u[i] = e.u;
        v[i] = e.v;
        w[i] = e.w;
    }
}

// What the lanes' watertight test finds: where it hits before each lane's limit, and t, u, v.
template <class L>
struct WatertightLaneHits {
    L hit, t, u, v;
};

// The watertight test lane by lane (see intersectWatertight: the same operations in the same
// order, the rejections as masks): one triangle per lane against one ray (the blocks), or one
// triangle against a ray per lane (the packets). load(vertex, axis) gives the lanes' VertexBlock::p0,
// p1 or p2 (a pointer to the member) on one axis; N, the lanes' count. Always inlined, as
// mollerTrumboreLanes is.
template <class Lanes, int N, class Load>
[[gnu::always_inline]] inline WatertightLaneHits<typename Lanes::Type> watertightLaneTest(
    const Load& load, const ShearedRayLanesOf<Lanes>& ray, const typename Lanes::Type& limit) {
    using L = typename Lanes::Type;
    // Vertex p relative to the origin, sheared: its x, y and (unscaled) z.
    const auto project = [&](auto vertex, L& x, L& y, L& z) __attribute__((always_inline)) {
        z = load(vertex, ray.kz) - ray.origin[2];
        x = (load(vertex, ray.kx) - ray.origin[0]) - ray.sx * z;
        y = (load(vertex, ray.ky) - ray.origin[1]) - ray.sy * z;
    };
    L ax, ay, az, bx, by, bz, cx, cy, cz;
    project(&VertexBlock::p0, ax, ay, az);
    project(&VertexBlock::p1, bx, by, bz);
    project(&VertexBlock::p2, cx, cy, cz);
    L u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    const L zero = Lanes::all(0);
    const unsigned exact = laneBits(notEqual(u, zero) & notEqual(v, zero) & notEqual(w, zero));
    if (exact != (1u << N) - 1) [[unlikely]] {
        alignas(64) Real xy[6][N], us[N], vs[N], ws[N];
        const L* projected[6] = {&ax, &ay, &bx, &by, &cx, &cy};
        for (int k = 0; k < 6; ++k) storeLanes(xy[k], *projected[k]);
        storeLanes(us, u);
        storeLanes(vs, v);
        storeLanes(ws, w);
        refineEdgeFunctions<N>(~exact & ((1u << N) - 1), xy, us, vs, ws);
        u = Lanes::load(us);
        v = Lanes::load(vs);
        w = Lanes::load(ws);
    }
    const L inside = (lessEqual(zero, u) & lessEqual(zero, v) & lessEqual(zero, w)) |
                     (lessEqual(u, zero) & lessEqual(v, zero) & lessEqual(w, zero));
    const L det = u + v + w;
    const L scaled = u * (ray.sz * az) + v * (ray.sz * bz) + w * (ray.sz * cz);
    const L invDet = Lanes::all(1) / det;
    const L t = scaled * invDet;
    return {inside & notEqual(det, zero) & lessThan(zero, t) & lessThan(t, limit), t, v * invDet, w * invDet};
}

// The test with one triangle per lane, as LaneHits.
template <class Lanes, int N, class Load>
[[gnu::always_inline]] inline LaneHits<N> watertightLanes(const Load& load, const ShearedRayLanesOf<Lanes>& ray,
                                                          Real tMax) {
    const auto h = watertightLaneTest<Lanes, N>(load, ray, Lanes::all(tMax));
    return LaneHits<N>::of(h.hit, h.t, h.u, h.v);
}

// The test on one block's triangles.
inline BlockHits intersectBlock(const VertexBlock& b, const ShearedRayLanes& ray, Real tMax) {
    return watertightLanes<BaseLanes, kSimdWidth>([&](auto vertex, int axis) { return loadLanes((b.*vertex)[axis]); },
                                                  ray, tMax);
}

}  // namespace rt
