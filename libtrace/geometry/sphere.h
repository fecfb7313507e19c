// Sphere primitive: centre and radius, stored flat in Primitives::spheres.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/aabb.h"
#include "core/ray.h"

namespace rt {

struct Sphere {
    static constexpr const char* kName = "sphere";
    // A sphere test costs the trees 0.6 (thesis 2.1.2: a miss needs no square root; measured as
    // the best C_T/C_I ratio on each kind of scene when a triangle cost 1.5, docs/trees.md): as
    // much as a triangle's 0.6 since the leaves test triangles in blocks and spheres one by one.
    static constexpr double kTestCost = 1;
    Vec3 center;
    Real radius = 0;

    Aabb bounds() const {
        const Vec3 r{radius, radius, radius};
        return {center - r, center + r};
    }
    // Unit outward normal at a point on the surface. Normalised rather than divided by the
    // radius: a computed hit point lies off a small sphere by rounding, and a normal that is
    // not unit would make reflected directions that are not unit either (see intersectSphere).
    Vec3 normal(const Vec3& point) const { return normalize(point - center); }
    Real area() const { return 4 * kPi * radius * radius; }
    bool degenerate() const { return !(radius > 0) || !std::isfinite(radius) || !isFinite(center); }
    // Latitude and longitude from u and v (not uniform over the area: test rays need no more).
    Vec3 surfacePoint(Real u, Real v) const {
        const Real cosTheta = 1 - 2 * u, sinTheta = std::sqrt(std::max(Real(0), 1 - cosTheta * cosTheta));
        const Real phi = 2 * kPi * v;
        return center + Vec3{sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta} * radius;
    }
};

// The geometric test of thesis 2.1.2 (Glassner, thesis [3]); the ray direction must be
// unit length. It rejects a sphere behind the ray before taking any square root, which
// is why the thesis prefers it to the algebraic form. From inside the sphere the far
// intersection is returned. A hit with 0 < t < tMax sets t and returns true.
inline bool intersectSphere(const Sphere& s, const Ray& ray, Real tMax, Real& t) {
    assert(isUnitLength(ray.direction));
    const Vec3 l = s.center - ray.origin;
    const Real tca = dot(l, ray.direction);  // distance to the point closest to the centre
    const Real l2 = dot(l, l);
    const Real r2 = s.radius * s.radius;
    const bool outside = l2 > r2;
    if (outside && tca < 0) return false;  // sphere lies behind the ray
    const Real d2 = l2 - tca * tca;        // squared distance of the centre from the ray
    if (d2 > r2) return false;
    const Real thc = std::sqrt(r2 - d2);
    Real tt = outside ? tca - thc : tca + thc;
    if (!(tt > 0)) tt = tca + thc;  // origin on the surface: take the far side
    if (!(tt > 0 && tt < tMax)) return false;
    t = tt;
    return true;
}

inline bool intersect(const Sphere& s, const Ray& ray, Real tMax, Hit& hit) {
    if (!intersectSphere(s, ray, tMax, hit.t)) return false;
    hit.u = hit.v = 0;
    return true;
}
inline bool intersectsAny(const Sphere& s, const Ray& ray, Real tMax) {
    Real t;
    return intersectSphere(s, ray, tMax, t);
}

}  // namespace rt
