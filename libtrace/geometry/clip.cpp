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

// Where the edge from a to b crosses the plane x[axis] = pos, with the plane's coordinate
// exactly, so that rounding cannot move it outside the box.
Vec3 crossing(const Vec3& a, const Vec3& b, int axis, Real pos) {
    Vec3 p = a + (b - a) * ((pos - a[axis]) / (b[axis] - a[axis]));
    p[axis] = pos;
    return p;
}

// Keeps the part of `in` on the side of the plane x[axis] = pos given by `keepAbove`.
Polygon clipToPlane(const Polygon& in, int axis, Real pos, bool keepAbove) {
    Polygon out;
    auto inside = [&](const Vec3& p) { return keepAbove ? p[axis] >= pos : p[axis] <= pos; };
    for (int i = 0; i < in.n; ++i) {
        const Vec3& a = in.v[i];
        const Vec3& b = in.v[i + 1 < in.n ? i + 1 : 0];
        const bool aIn = inside(a), bIn = inside(b);
        if (aIn) out.v[out.n++] = a;
        if (aIn != bIn) out.v[out.n++] = crossing(a, b, axis, pos);
    }
    return out;
}

// The triangle clipped to the box. A plane the whole triangle lies inside of would return the
// polygon unchanged: skip it. In a KD build most triangles cross one or two of a voxel's
// planes, not six.
Polygon clipToBox(const Triangle& tri, const Aabb& triBounds, const Aabb& box) {
    Polygon poly;
    poly.v[0] = tri.p0;
    poly.v[1] = tri.p1;
    poly.v[2] = tri.p2;
    poly.n = 3;
    for (int a = 0; a < 3 && poly.n > 0; ++a) {
        if (triBounds.lo[a] < box.lo[a]) poly = clipToPlane(poly, a, box.lo[a], true);
        if (triBounds.hi[a] > box.hi[a]) poly = clipToPlane(poly, a, box.hi[a], false);
    }
    return poly;
}

// The bounds of what was left of the triangle in `box`. Rounding can lose a sliver the exact
// test still sees; such a triangle is kept, conservatively.
Aabb keptBounds(const Aabb& bounds, const Triangle& tri, const Aabb& triBounds, const Aabb& box) {
    if (bounds.empty() && overlaps(tri, box)) return intersection(triBounds, box);
    return intersection(bounds, box);
}

}  // namespace

Aabb clippedBounds(const Triangle& tri, const Aabb& box) {
    const Aabb triBounds = tri.bounds();
    const Polygon poly = clipToBox(tri, triBounds, box);
    Aabb bounds;
    for (int i = 0; i < poly.n; ++i) bounds.extend(poly.v[i]);
    return keptBounds(bounds, tri, triBounds, box);
}

// The polygon in the box is clipped once and then cut by the plane in one pass over its
// edges (Sutherland-Hodgman with both sides kept): a vertex counts for the side or sides it
// lies on, and an edge crossing the plane adds its crossing point, on the plane exactly, to both.
SplitBounds splitClippedBounds(const Triangle& tri, const Aabb& box, int axis, Real pos) {
    const Aabb triBounds = tri.bounds();
    const Polygon poly = clipToBox(tri, triBounds, box);
    SplitBounds split;
    for (int i = 0; i < poly.n; ++i) {
        const Vec3& a = poly.v[i];
        const Vec3& b = poly.v[i + 1 < poly.n ? i + 1 : 0];
        if (a[axis] <= pos) split.below.extend(a);
        if (a[axis] >= pos) split.above.extend(a);
        if ((a[axis] < pos && b[axis] > pos) || (a[axis] > pos && b[axis] < pos)) {
            const Vec3 p = crossing(a, b, axis, pos);
            split.below.extend(p);
            split.above.extend(p);
        }
    }
    const SplitBounds halves = splitBox(box, axis, pos);
    split.below = keptBounds(split.below, tri, triBounds, halves.below);
    split.above = keptBounds(split.above, tri, triBounds, halves.above);
    return split;
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
