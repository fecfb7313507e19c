#include "render/surface.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

// The interpolated vertex normal of a smooth triangle, each vertex normal turned to the side
// the geometric normal faces, and the shadow origin moved onto the smooth surface; no change
// for a flat triangle (zero normals).
void applyVertexNormals(const Triangle& tri, const CornerNormals& corners, const Hit& hit, SurfacePoint& s) {
    Vec3 normals[3];
    for (int c = 0; c < 3; ++c) {
        normals[c] = corners.corner(c);
        if (dot(normals[c], s.geometricNormal) < 0) normals[c] = -normals[c];
    }
    const Vec3 n = normals[0] * (1 - hit.u - hit.v) + normals[1] * hit.u + normals[2] * hit.v;
    const Real len = length(n);
    if (!(len > 0)) return;
    s.shadingNormal = n / len;
    s.shadowOrigin = offsetToSmoothSurface(s.point, tri, normals, hit.u, hit.v);
}

void applyTriangleData(const Primitives& primitives, std::uint32_t index, const Hit& hit, SurfacePoint& s) {
    const TriangleShading& data = primitives.triangleShading();
    if (const CornerNormals* normals = data.normals.find(index))
        applyVertexNormals(primitives.all<Triangle>()[index], *normals, hit, s);
    if (const CornerUvs* uvs = data.uvs.find(index)) {
        const auto uv = uvs->at(hit.u, hit.v);
        s.u = uv[0];
        s.v = uv[1];
    }
    if (const CornerColors* colors = data.colors.find(index)) {
        const auto rgb = colors->at(hit.u, hit.v);
        s.tint = {float(rgb[0]), float(rgb[1]), float(rgb[2])};
    }
}

}  // namespace

Real secondaryRayOffset(const Primitives& primitives) {
    constexpr Real kRelative = sizeof(Real) == sizeof(float) ? Real(1e-4) : Real(1e-7);
    const Aabb box = primitives.bounds();
    if (box.empty()) return kRelative;
    Real scale = std::max(length(box.diagonal()), Real(1e-3));
    for (int a = 0; a < 3; ++a) scale = std::max({scale, std::abs(box.lo[a]), std::abs(box.hi[a])});
    return kRelative * scale;
}

SurfacePoint surfaceAt(const Primitives& primitives, const Ray& ray, const Hit& hit) {
    SurfacePoint s;
    s.point = ray.at(hit.t);
    s.geometricNormal = primitives.normal(hit.prim, s.point);
    s.frontFace = dot(s.geometricNormal, ray.direction) <= 0;
    if (!s.frontFace) s.geometricNormal = -s.geometricNormal;  // two-sided surfaces
    s.shadingNormal = s.geometricNormal;
    s.shadowOrigin = s.point;
    if (primitives.triangleShading().empty()) return s;
    if (const std::optional<std::uint32_t> index = primitives.indexIn<Triangle>(hit.prim))
        applyTriangleData(primitives, *index, hit, s);
    return s;
}

Vec3 offsetToSmoothSurface(const Vec3& p, const Triangle& tri, const Vec3 (&normals)[3], Real b1, Real b2) {
    const Vec3 corners[3] = {tri.p0, tri.p1, tri.p2};
    const Real weights[3] = {1 - b1 - b2, b1, b2};
    Vec3 moved = p;
    for (int c = 0; c < 3; ++c) {
        const Real below = std::min(Real(0), dot(p - corners[c], normals[c]));  // how far p is under the plane
        moved -= normals[c] * (weights[c] * below);
    }
    return moved;
}

Vec3 keepReflectionAbove(const Vec3& n, const Vec3& ng, const Vec3& toViewer) {
    const Real iz = dot(toViewer, ng);
    const Real least = std::min(Real(0.9) * iz, Real(0.01));
    if (2 * dot(n, toViewer) * dot(n, ng) - iz >= least) return n;  // the mirror direction's height
    // In the plane of ng and n, n' = x sin(a) + ng cos(a) mirrors the view to the height
    // ix sin(2a) + iz cos(2a) = r cos(2a - phi), ix the viewer's component along x and
    // phi = atan2(ix, iz): the largest angle a (the least turn back from n) where it is `least`.
    const Vec3 across = n - ng * dot(n, ng);
    const Real width = length(across);
    if (!(width > 0)) return ng;
    const Vec3 x = across / width;
    const Real ix = dot(toViewer, x);
    const Real r = std::hypot(ix, iz);
    if (!(r > 0)) return ng;
    const Real a = (std::atan2(ix, iz) + std::acos(std::min(least / r, Real(1)))) / 2;
    return x * std::sin(a) + ng * std::cos(a);
}

}  // namespace rt
