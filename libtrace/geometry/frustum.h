// Cylinders and cones: finite, capped, along any axis (an extension of the thesis, whose
// chapter 5 names them as the next primitives). Both are a frustum of a cone: two end
// centres and a radius at each end; a cylinder has equal radii, and a cone's radius may be
// zero at one end. One file holds all a kind provides (as Mitsuba 3 keeps one file per
// shape): bounds, clipped bounds, box overlap, intersection and normal.
#pragma once

#include <cmath>
#include <utility>

#include "core/aabb.h"
#include "core/ray.h"

namespace rt {

struct Frustum {
    Vec3 base, top;  // the centres of the two end discs
    Real baseRadius = 0, topRadius = 0;

    struct Axis {
        Vec3 w;       // unit, from base to top
        Real height;  // distance from base to top
    };
    Axis axis() const {
        const Vec3 d = top - base;
        const Real h = length(d);
        return {d / h, h};
    }

    // Exact: the frustum is the convex hull of its two end discs, and a disc of radius r
    // with unit normal w reaches r * sqrt(1 - w_i^2) from its centre on axis i.
    Aabb bounds() const;
    Real area() const;  // side and both caps
    // Unit outward normal of the side or cap that `point` lies closest to.
    Vec3 normal(const Vec3& point) const;
    // A point on the side: u along the axis from base to top, v around it.
    Vec3 surfacePoint(Real u, Real v) const;
    bool degenerate() const;
    // True if the point is inside the solid (or on its surface).
    bool containsPoint(const Vec3& p) const;
};

struct Cylinder : Frustum {
    static constexpr const char* kName = "cylinder";
    // Two quadratic roots and two caps against a triangle's one test: 2.25, a first estimate
    // (1.5 of the triangle's first cost 1.5, kept when it became 0.75 and 0.6), not yet tuned.
    static constexpr double kTestCost = 3.75;
};

struct Cone : Frustum {
    static constexpr const char* kName = "cone";
    static constexpr double kTestCost = 3.75;
};

// The side (a quadric) and both caps (discs); a hit with 0 < t < tMax sets t, u (from 0 at
// the base to 1 at the top) and v = 0, and returns true. From inside, the far side is hit.
// In the header, as the sphere's and the triangle's tests are: a call the compiler cannot
// see into, in the trees' leaf loop, makes it reload the traversal's state from memory
// around it even where the call is never taken (docs/benchmarks.md: 17 % more
// instructions per ray on scenes of spheres).
inline bool intersect(const Frustum& f, const Ray& ray, Real tMax, Hit& hit) {
    // Plain variables, not a structured binding: the lambdas below capture them, which clang 14
    // does not allow for bindings (C++20 does).
    const Frustum::Axis axis = f.axis();
    const Vec3 w = axis.w;
    const Real height = axis.height;
    const Real slope = (f.topRadius - f.baseRadius) / height;
    const Vec3 q0 = ray.origin - f.base;
    const Real h0 = dot(q0, w), dh = dot(ray.direction, w);
    // Off-axis parts of the origin and the direction: the side is |P + t D| = r(h(t)).
    const Vec3 P = q0 - w * h0, D = ray.direction - w * dh;
    const Real r0 = f.baseRadius + slope * h0, dr = slope * dh;
    Real best = tMax, bestU = 0;
    const auto keepNearer = [&](Real t, Real u) {
        if (t > 0 && t < best) best = t, bestU = u;
    };
    const auto sideAt = [&](Real t) {
        const Real h = h0 + t * dh;
        if (h >= 0 && h <= height) keepNearer(t, h / height);
    };
    const Real a = dot(D, D) - dr * dr, b = 2 * (dot(P, D) - r0 * dr), c = dot(P, P) - r0 * r0;
    const Real disc = b * b - 4 * a * c;
    if (a != 0 && disc >= 0) {
        // The stable form: no cancellation between -b and the root.
        const Real q = Real(-0.5) * (b + std::copysign(std::sqrt(disc), b));
        sideAt(q / a);
        if (q != 0) sideAt(c / q);
    } else if (a == 0 && b != 0) {
        sideAt(-c / b);  // parallel to a line of the cone: one crossing
    }
    if (dh != 0) {
        for (const auto& [capH, radius] : {std::pair{Real(0), f.baseRadius}, std::pair{height, f.topRadius}}) {
            const Real t = (capH - h0) / dh;
            const Vec3 off = P + D * t;
            if (dot(off, off) <= radius * radius) keepNearer(t, capH / height);
        }
    }
    if (!(best < tMax)) return false;
    hit.t = best;
    hit.u = bestU;
    hit.v = 0;
    return true;
}
inline bool intersectsAny(const Frustum& f, const Ray& ray, Real tMax) {
    Hit scratch;
    return intersect(f, ray, tMax, scratch);
}

// Tight and conservative: the axis is cut into slabs, each slab's piece bounded by its two
// discs' bounds, and the union of those boxes clipped to `box` is returned; empty if the box
// lies wholly inside the solid (only the surface can be hit) or no slab box meets it.
Aabb clippedBounds(const Frustum& f, const Aabb& box);
// Whether the surface may meet the closed box: clippedBounds is not empty. Conservative (a
// box near the surface within a slab's corners may be reported as overlapping), never misses.
bool overlaps(const Frustum& f, const Aabb& box);

}  // namespace rt
