#include "geometry/overlap.h"

#include <cmath>

namespace rt {

namespace {

// True if the projections of the triangle (vertices relative to the box centre) and of
// the box (half-extents h) onto `axis` are disjoint, i.e. `axis` separates them.
bool separatedOn(const Vec3& axis, const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& h) {
    const Real p0 = dot(axis, v0), p1 = dot(axis, v1), p2 = dot(axis, v2);
    const Real r = h.x * std::abs(axis.x) + h.y * std::abs(axis.y) + h.z * std::abs(axis.z);
    return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

}  // namespace

bool overlaps(const Triangle& tri, const Aabb& box) {
    const Vec3 c = box.center();
    const Vec3 h = box.diagonal() * Real(0.5);
    const Vec3 v0 = tri.p0 - c, v1 = tri.p1 - c, v2 = tri.p2 - c;

    // The box's face normals: the triangle's bounds against the box.
    for (int a = 0; a < 3; ++a) {
        if (std::min({v0[a], v1[a], v2[a]}) > h[a] || std::max({v0[a], v1[a], v2[a]}) < -h[a]) return false;
    }
    // The nine edge-axis cross products.
    const Vec3 edges[3] = {v1 - v0, v2 - v1, v0 - v2};
    const Vec3 units[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const Vec3& e : edges) {
        for (const Vec3& u : units) {
            if (separatedOn(cross(e, u), v0, v1, v2, h)) return false;
        }
    }
    // The triangle's plane.
    return !separatedOn(cross(edges[0], edges[1]), v0, v1, v2, h);
}

bool overlaps(const Sphere& sphere, const Aabb& box) {
    Real nearest = 0, farthest = 0;
    for (int a = 0; a < 3; ++a) {
        const Real toLo = sphere.center[a] - box.lo[a];
        const Real toHi = sphere.center[a] - box.hi[a];
        if (toLo < 0)
            nearest += toLo * toLo;
        else if (toHi > 0)
            nearest += toHi * toHi;
        farthest += std::max(toLo * toLo, toHi * toHi);
    }
    const Real r2 = sphere.radius * sphere.radius;
    return nearest <= r2 && r2 <= farthest;
}

}  // namespace rt
