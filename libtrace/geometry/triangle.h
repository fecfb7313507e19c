// Triangle primitive: three vertices, stored flat in Primitives::triangles.
#pragma once

#include "core/aabb.h"
#include "core/ray.h"

namespace rt {

struct Triangle {
    static constexpr const char* kName = "triangle";
    static constexpr double kTestCost = 1;  // the unit the SAH's C_I is given in
    Vec3 p0, p1, p2;

    Aabb bounds() const {
        Aabb b;
        b.extend(p0);
        b.extend(p1);
        b.extend(p2);
        return b;
    }
    // Geometric normal, unit length, oriented by the winding p0 -> p1 -> p2.
    Vec3 normal() const { return normalize(cross(p1 - p0, p2 - p0)); }
    Vec3 normal(const Vec3& /*point*/) const { return normal(); }
    Real area() const { return Real(0.5) * length(cross(p1 - p0, p2 - p0)); }
    bool degenerate() const { return !(area() > 0) || !isFinite(p0) || !isFinite(p1) || !isFinite(p2); }
    // Folds the unit square onto the triangle.
    Vec3 surfacePoint(Real u, Real v) const {
        if (u + v > 1) u = 1 - u, v = 1 - v;
        return p0 + (p1 - p0) * u + (p2 - p0) * v;
    }
};

// Moller-Trumbore (thesis [5]): a hit with 0 < t < tMax sets t, u and v and returns true.
// Rays parallel to the triangle's plane (determinant exactly zero) never hit; a ray
// through an edge or vertex hits both neighbours, so closed meshes have no cracks.
inline bool intersectTriangle(const Triangle& tri, const Ray& ray, Real tMax, Real& t, Real& u, Real& v) {
    const Vec3 e1 = tri.p1 - tri.p0;
    const Vec3 e2 = tri.p2 - tri.p0;
    const Vec3 p = cross(ray.direction, e2);
    const Real det = dot(e1, p);
    if (det == 0) return false;
    const Real invDet = 1 / det;
    const Vec3 s = ray.origin - tri.p0;
    const Real uu = dot(s, p) * invDet;
    if (uu < 0 || uu > 1) return false;
    const Vec3 q = cross(s, e1);
    const Real vv = dot(ray.direction, q) * invDet;
    if (vv < 0 || uu + vv > 1) return false;
    const Real tt = dot(e2, q) * invDet;
    if (!(tt > 0 && tt < tMax)) return false;
    t = tt;
    u = uu;
    v = vv;
    return true;
}

inline bool intersect(const Triangle& tri, const Ray& ray, Real tMax, Hit& hit) {
    return intersectTriangle(tri, ray, tMax, hit.t, hit.u, hit.v);
}
inline bool intersectsAny(const Triangle& tri, const Ray& ray, Real tMax) {
    Real t, u, v;
    return intersectTriangle(tri, ray, tMax, t, u, v);
}

}  // namespace rt
