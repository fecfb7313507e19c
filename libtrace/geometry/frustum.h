// Cylinders and cones: finite, capped, along any axis (an extension of the thesis, whose
// chapter 5 names them as the next primitives). Both are a frustum of a cone: two end
// centres and a radius at each end; a cylinder has equal radii, and a cone's radius may be
// zero at one end. One file holds all a kind provides (as Mitsuba 3 keeps one file per
// shape): bounds, clipped bounds, box overlap, intersection and normal.
#pragma once

#include "core/aabb.h"
#include "core/ray.h"

namespace rt {

struct Frustum {
    Vec3 base, top;  // the centres of the two end discs
    Real baseRadius = 0, topRadius = 0;

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
    // Two quadratic roots and two caps against a triangle's one test: measured like the
    // sphere's 0.4 would be (docs/trees.md); a first estimate, not yet tuned.
    static constexpr double kTestCost = 1.5;
};

struct Cone : Frustum {
    static constexpr const char* kName = "cone";
    static constexpr double kTestCost = 1.5;
};

// The side (a quadric) and both caps (discs); a hit with 0 < t < tMax sets t, u (from 0 at
// the base to 1 at the top) and v = 0, and returns true. From inside, the far side is hit.
bool intersect(const Frustum& f, const Ray& ray, Real tMax, Hit& hit);
bool intersectsAny(const Frustum& f, const Ray& ray, Real tMax);

// Tight and conservative: the axis is cut into slabs, each slab's piece bounded by its two
// discs' bounds, and the union of those boxes clipped to `box` is returned; empty if the box
// lies wholly inside the solid (only the surface can be hit) or no slab box meets it.
Aabb clippedBounds(const Frustum& f, const Aabb& box);
// Whether the surface may meet the closed box: clippedBounds is not empty. Conservative (a
// box near the surface within a slab's corners may be reported as overlapping), never misses.
bool overlaps(const Frustum& f, const Aabb& box);

}  // namespace rt
