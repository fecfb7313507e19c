// Disks: a centre, the unit normal of their plane and a radius (an extension of the thesis, in
// the spirit of its chapter 5's next primitives). Two-sided, without thickness: a ray in the
// disk's plane misses it. One file holds all the kind provides (as Mitsuba 3 keeps one file per
// shape): bounds, clipped bounds, box overlap, intersection and normal. It has no block
// (geometry/leaf_block.h): the leaves test disks one at a time, as a block for a third kind cost
// the scenes without disks 3 to 8 % more instructions per ray (docs/benchmarks.md).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/aabb.h"
#include "core/ray.h"

namespace rt {

struct Disk {
    Vec3 center;
    Vec3 planeNormal;  // unit
    Real radius = 0;

    static constexpr const char* kName = "disk";
    // A plane distance and a squared distance, against a triangle's Moller-Trumbore: about a
    // triangle's cost, a first estimate (not yet measured as docs/trees.md describes).
    static constexpr double kTestCost = 1;

    // Exact: a circle of radius r with unit normal n reaches r * sqrt(1 - n_i^2) from its centre on
    // axis i.
    Aabb bounds() const {
        Vec3 reach;
        for (int axis = 0; axis < 3; ++axis)
            reach[axis] = radius * std::sqrt(std::max(Real(0), 1 - planeNormal[axis] * planeNormal[axis]));
        return {center - reach, center + reach};
    }
    Real area() const { return kPi * radius * radius; }
    Vec3 normal(const Vec3&) const { return planeNormal; }
    bool degenerate() const {
        return !(radius > 0) || !std::isfinite(radius) || !isFinite(center) || !isFinite(planeNormal) ||
               !isUnitLength(planeNormal);
    }
    // u, the squared distance from the centre in radii (uniform over the area), and v around it.
    Vec3 surfacePoint(Real u, Real v) const {
        const Vec3 helper = std::abs(planeNormal.x) > Real(0.9) ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
        const Vec3 s = normalize(cross(helper, planeNormal)), t = cross(planeNormal, s);
        const Real phi = 2 * kPi * v, r = radius * std::sqrt(u);
        return center + (s * std::cos(phi) + t * std::sin(phi)) * r;
    }
};

// The ray meets the plane at t = dot(centre - origin, n) / dot(direction, n), and the point is on
// the disk when its squared distance from the centre is at most r^2. A hit with 0 < t < tMax sets
// t, u (that squared distance in radii squared) and v = 0. Edge-on (dot(direction, n) = 0) t is
// infinite or NaN, which no hit condition passes. In the header, as every kind's ray tests
// (docs/architecture.md).
inline bool intersect(const Disk& d, const Ray& ray, Real tMax, Hit& hit) {
    const Vec3 l = d.center - ray.origin;
    const Real t = dot(l, d.planeNormal) / dot(ray.direction, d.planeNormal);
    const Vec3 q = ray.direction * t - l;  // from the centre to the hit point
    const Real q2 = dot(q, q), r2 = d.radius * d.radius;
    if (!(Real(0) < t && t < tMax && q2 <= r2)) return false;
    hit.t = t;
    hit.u = q2 / r2;
    hit.v = 0;
    return true;
}
inline bool intersectsAny(const Disk& d, const Ray& ray, Real tMax) {
    Hit scratch;
    return intersect(d, ray, tMax, scratch);
}

// Conservative: the disk's bounds clipped to the box, or empty when the disk's plane misses the
// box they leave. Never smaller than the part of the disk inside the box; larger where the box
// cuts the disk's rim (the exact part is bounded by a polygon's and ellipse arcs' extremes, not
// worth their cost: a KD node sees a disk through this, so the cost is a few misplaced split
// candidates). The plane test allows for the rounding of its sums.
inline Aabb clippedBounds(const Disk& d, const Aabb& box) {
    const Aabb clipped = intersection(d.bounds(), box);
    if (clipped.empty()) return {};
    const Vec3 middle = clipped.center() - d.center, half = clipped.diagonal() * Real(0.5);
    Real distance = 0, reach = 0, scale = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const Real n = d.planeNormal[axis];
        distance += n * middle[axis];
        reach += std::abs(n) * half[axis];
        scale += std::abs(n) * (std::abs(clipped.center()[axis]) + std::abs(d.center[axis]) + half[axis]);
    }
    const Real slack = 64 * std::numeric_limits<Real>::epsilon() * scale;
    return std::abs(distance) <= reach + slack ? clipped : Aabb{};
}
inline bool overlaps(const Disk& d, const Aabb& box) { return !clippedBounds(d, box).empty(); }

}  // namespace rt
