#include "geometry/clip.h"

#include <array>
#include <cmath>

#include "geometry/overlap.h"

namespace rt {

namespace {

// A convex polygon of at most 3 + 6 vertices: each clip plane adds at most one.
struct Polygon {
    std::array<Vec3, 9> v;
    int n = 0;
};

// Keeps the part of `in` on the side of the plane x[axis] = pos given by `keepAbove`.
// New vertices get the plane's coordinate exactly, so that rounding cannot move them
// outside the box.
Polygon clipToPlane(const Polygon& in, int axis, Real pos, bool keepAbove) {
    Polygon out;
    auto inside = [&](const Vec3& p) { return keepAbove ? p[axis] >= pos : p[axis] <= pos; };
    for (int i = 0; i < in.n; ++i) {
        const Vec3& a = in.v[i];
        const Vec3& b = in.v[i + 1 < in.n ? i + 1 : 0];
        const bool aIn = inside(a), bIn = inside(b);
        if (aIn) out.v[out.n++] = a;
        if (aIn != bIn) {
            Vec3 p = a + (b - a) * ((pos - a[axis]) / (b[axis] - a[axis]));
            p[axis] = pos;
            out.v[out.n++] = p;
        }
    }
    return out;
}

}  // namespace

Aabb clippedBounds(const Triangle& tri, const Aabb& box) {
    Polygon poly;
    poly.v[0] = tri.p0;
    poly.v[1] = tri.p1;
    poly.v[2] = tri.p2;
    poly.n = 3;
    // A plane the whole triangle lies inside of would return the polygon unchanged: skip it.
    // In a KD build most triangles cross one or two of a voxel's planes, not six.
    const Aabb triBounds = tri.bounds();
    for (int a = 0; a < 3 && poly.n > 0; ++a) {
        if (triBounds.lo[a] < box.lo[a]) poly = clipToPlane(poly, a, box.lo[a], true);
        if (triBounds.hi[a] > box.hi[a]) poly = clipToPlane(poly, a, box.hi[a], false);
    }
    Aabb bounds;
    for (int i = 0; i < poly.n; ++i) bounds.extend(poly.v[i]);
    // Rounding can lose a sliver the exact test still sees; keep such a triangle, conservatively.
    if (bounds.empty() && overlaps(tri, box)) bounds = tri.bounds();
    return intersection(bounds, box);
}

Aabb clippedBounds(const Sphere& sphere, const Aabb& box) {
    if (!overlaps(sphere, box)) return {};
    const Real r2 = sphere.radius * sphere.radius;
    Aabb bounds;
    for (int a = 0; a < 3; ++a) {
        // Squared distance from the centre to the box's rectangle on the other two axes.
        Real d2 = 0;
        for (int b = 0; b < 3; ++b) {
            if (b == a) continue;
            const Real c = sphere.center[b];
            const Real d = c < box.lo[b] ? box.lo[b] - c : (c > box.hi[b] ? c - box.hi[b] : 0);
            d2 += d * d;
        }
        const Real reach = std::sqrt(std::max(r2 - d2, Real(0)));
        bounds.lo[a] = std::max(box.lo[a], sphere.center[a] - reach);
        bounds.hi[a] = std::min(box.hi[a], sphere.center[a] + reach);
    }
    return bounds;
}

}  // namespace rt
