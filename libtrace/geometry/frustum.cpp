#include "geometry/frustum.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rt {

namespace {

// Bounds of a disc: centre c, unit normal w, radius r.
Aabb discBounds(const Vec3& c, const Vec3& w, Real r) {
    Vec3 e;
    for (int i = 0; i < 3; ++i) e[i] = r * std::sqrt(std::max(Real(0), 1 - w[i] * w[i]));
    return {c - e, c + e};
}

// Rounding in discBounds must not cut off the surface: grow a box by a few ulps of its size.
Aabb padded(const Aabb& b) {
    const Real scale = std::max(
        {std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.lo.z), std::abs(b.hi.x), std::abs(b.hi.y), std::abs(b.hi.z)});
    const Real pad = 16 * std::numeric_limits<Real>::epsilon() * scale;
    const Vec3 p{pad, pad, pad};
    return {b.lo - p, b.hi + p};
}

// Two unit vectors perpendicular to w and to each other.
void perpendiculars(const Vec3& w, Vec3& a, Vec3& b) {
    a = normalize(std::abs(w.x) < Real(0.9) ? cross(w, Vec3{1, 0, 0}) : cross(w, Vec3{0, 1, 0}));
    b = cross(w, a);
}

}  // namespace

Aabb Frustum::bounds() const {
    const Vec3 w = axis().w;
    Aabb b = discBounds(base, w, baseRadius);
    b.extend(discBounds(top, w, topRadius));
    return padded(b);
}

Real Frustum::area() const {
    const Real h = length(top - base);
    const Real slant = std::sqrt(h * h + (topRadius - baseRadius) * (topRadius - baseRadius));
    return kPi * ((baseRadius + topRadius) * slant + baseRadius * baseRadius + topRadius * topRadius);
}

Vec3 Frustum::normal(const Vec3& point) const {
    const auto [w, height] = axis();
    const Vec3 q = point - base;
    const Real h = dot(q, w);
    const Vec3 radial = q - w * h;
    const Real distance = length(radial);
    const Real slope = (topRadius - baseRadius) / height;
    // Distances to the two cap planes and (measured across the side) to the side.
    const Real toSide = std::abs(distance - (baseRadius + slope * h)) / std::sqrt(1 + slope * slope);
    if (std::abs(h) <= toSide && std::abs(h) <= std::abs(height - h)) return -w;
    if (std::abs(height - h) <= toSide || !(distance > 0)) return w;
    return normalize(radial / distance - w * slope);
}

Vec3 Frustum::surfacePoint(Real u, Real v) const {
    const auto [w, height] = axis();
    Vec3 a, b;
    perpendiculars(w, a, b);
    const Real phi = 2 * kPi * v;
    const Real r = baseRadius + (topRadius - baseRadius) * u;
    return base + w * (height * u) + (a * std::cos(phi) + b * std::sin(phi)) * r;
}

bool Frustum::degenerate() const {
    const bool finite = isFinite(base) && isFinite(top) && std::isfinite(baseRadius) && std::isfinite(topRadius);
    return !finite || !(length(top - base) > 0) || baseRadius < 0 || topRadius < 0 ||
           !(baseRadius > 0 || topRadius > 0);
}

bool Frustum::containsPoint(const Vec3& p) const {
    const auto [w, height] = axis();
    const Vec3 q = p - base;
    const Real h = dot(q, w);
    if (h < 0 || h > height) return false;
    const Real r = baseRadius + (topRadius - baseRadius) * (h / height);
    return dot(q - w * h, q - w * h) <= r * r;
}

Aabb clippedBounds(const Frustum& f, const Aabb& box) {
    bool allCornersInside = true;
    for (int i = 0; i < 8 && allCornersInside; ++i)
        allCornersInside =
            f.containsPoint({(i & 1 ? box.hi : box.lo).x, (i & 2 ? box.hi : box.lo).y, (i & 4 ? box.hi : box.lo).z});
    if (allCornersInside) return {};  // the solid is convex: the box lies inside, off the surface
    constexpr int kSlabs = 8;
    const Vec3 w = f.axis().w;
    Aabb result;  // empty
    for (int s = 0; s < kSlabs; ++s) {
        const Real u0 = Real(s) / kSlabs, u1 = Real(s + 1) / kSlabs;
        Aabb slab = discBounds(f.base + (f.top - f.base) * u0, w, f.baseRadius + (f.topRadius - f.baseRadius) * u0);
        slab.extend(discBounds(f.base + (f.top - f.base) * u1, w, f.baseRadius + (f.topRadius - f.baseRadius) * u1));
        const Aabb inside = intersection(padded(slab), box);
        if (!inside.empty()) result.extend(inside);
    }
    return result;
}

bool overlaps(const Frustum& f, const Aabb& box) { return !clippedBounds(f, box).empty(); }

}  // namespace rt
