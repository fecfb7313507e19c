// Axis-aligned bounding box: the voxel of the BSP and KD trees (thesis 2.4, 2.5).
#pragma once

#include "core/ray.h"
#include "core/vec3.h"

namespace rt {

struct Aabb {
    // An empty box: extending it by anything yields that thing.
    Vec3 lo{kInfinity, kInfinity, kInfinity};
    Vec3 hi{-kInfinity, -kInfinity, -kInfinity};

    constexpr Aabb() = default;
    constexpr Aabb(const Vec3& lo_, const Vec3& hi_) : lo(lo_), hi(hi_) {}

    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    void extend(const Vec3& p) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    void extend(const Aabb& b) {
        lo = min(lo, b.lo);
        hi = max(hi, b.hi);
    }

    Vec3 diagonal() const { return hi - lo; }
    Vec3 center() const { return (lo + hi) * Real(0.5); }
    Real surfaceArea() const {
        if (empty()) return 0;
        const Vec3 d = diagonal();
        return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
    int longestAxis() const {
        const Vec3 d = diagonal();
        return d.x >= d.y ? (d.x >= d.z ? 0 : 2) : (d.y >= d.z ? 1 : 2);
    }
    bool operator==(const Aabb&) const = default;
};

inline Aabb intersection(const Aabb& a, const Aabb& b) { return {max(a.lo, b.lo), min(a.hi, b.hi)}; }

// Reciprocal direction, computed once per ray for the slab tests. A zero component
// becomes +-infinity, which the slab test below handles (Williams et al. 2005, thesis [17]).
inline Vec3 reciprocal(const Vec3& d) { return {Real(1) / d.x, Real(1) / d.y, Real(1) / d.z}; }

// Clips [t0, t1] to the part of the ray inside the box; false when nothing is left.
// A ray parallel to a slab gives (lo - o) * inf: +-inf when outside the slab (correctly
// rejecting or accepting), NaN when the origin lies exactly on the slab plane; the
// comparisons are written so that a NaN leaves the interval unchanged, treating such a
// ray as inside the slab.
inline bool clipRay(const Aabb& box, const Ray& ray, const Vec3& invDir, Real& t0, Real& t1) {
    for (int a = 0; a < 3; ++a) {
        Real tNear = (box.lo[a] - ray.origin[a]) * invDir[a];
        Real tFar = (box.hi[a] - ray.origin[a]) * invDir[a];
        if (tNear > tFar) std::swap(tNear, tFar);
        if (tNear > t0) t0 = tNear;
        if (tFar < t1) t1 = tFar;
        if (t0 > t1) return false;
    }
    return true;
}

inline std::ostream& operator<<(std::ostream& os, const Aabb& b) { return os << '[' << b.lo << " - " << b.hi << ']'; }

}  // namespace rt
