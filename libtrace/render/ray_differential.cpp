#include "render/ray_differential.h"

#include <algorithm>
#include <cmath>

#include "geometry/tangents.h"
#include "render/sampling.h"

namespace rt {

RayDifferential RayDifferential::cone(const Vec3& d, Real radius, Real spread) {
    Vec3 a, b;
    orthonormalBasis(d, a, b);
    return {a * radius, a * spread, b * radius, b * spread, true};
}

Real RayDifferential::radiusAt(Real t) const {
    return std::max(length(originX + directionX * t), length(originY + directionY * t));
}

void RayDifferential::footprintAt(const Vec3& d, Real t, const Vec3& n, Vec3& dpdx, Vec3& dpdy) const {
    // The offset ray's point at distance t, slid along the ray onto the tangent plane: first
    // order in the offset, as pbrt's intersection of the offset ray with the plane.
    const Real cosine = dot(n, d);
    if (!(std::abs(cosine) > 0)) return;
    const auto onPlane = [&](const Vec3& offset) { return offset - d * (dot(n, offset) / cosine); };
    dpdx = onPlane(originX + directionX * t);
    dpdy = onPlane(originY + directionY * t);
}

namespace {

// du/dx and dv/dx of a footprint offset `dp`: the least-squares solution of dp = dpdu du + dpdv dv.
struct UvChange {
    Real du = 0, dv = 0;
};

UvChange solve(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dp) {
    const Real a00 = dot(dpdu, dpdu), a01 = dot(dpdu, dpdv), a11 = dot(dpdv, dpdv);
    const Real det = a00 * a11 - a01 * a01;
    if (!(std::abs(det) > 0)) return {};
    const Real b0 = dot(dpdu, dp), b1 = dot(dpdv, dp);
    // Clamped, as pbrt-v4 does: a grazing footprint is huge, not infinite.
    const auto finite = [](Real v) { return std::isfinite(v) ? std::clamp(v, Real(-1e8), Real(1e8)) : Real(0); };
    return {finite((a11 * b0 - a01 * b1) / det), finite((a00 * b1 - a01 * b0) / det)};
}

}  // namespace

void setUvDerivatives(const Primitives& primitives, const Vec3& d, const Hit& hit, const RayDifferential& diff,
                      SurfacePoint& s) {
    const std::optional<std::uint32_t> index = primitives.indexIn<Triangle>(hit.prim);
    const CornerUvs* uvs = index ? primitives.triangleShading().uvs.find(*index) : nullptr;
    Vec3 dpdu, dpdv;
    if (!uvs || !uvDerivatives(primitives.all<Triangle>()[*index], *uvs, dpdu, dpdv)) return;
    Vec3 dpdx, dpdy;
    diff.footprintAt(d, hit.t, s.geometricNormal, dpdx, dpdy);
    const UvChange x = solve(dpdu, dpdv, dpdx), y = solve(dpdu, dpdv, dpdy);
    s.dudx = float(x.du);
    s.dvdx = float(x.dv);
    s.dudy = float(y.du);
    s.dvdy = float(y.dv);
    s.isotropic = diff.isotropic;
}

}  // namespace rt
