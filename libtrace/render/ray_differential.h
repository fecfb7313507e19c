// Ray differentials for texture filtering (Igehy 1999, "Tracing Ray Differentials"; pbrt-v4
// 10.1): how far the point a ray hits moves across the surface when the camera sample moves by
// one pixel (dp/dx, dp/dy), turned into the change of the texture coordinates (du/dx, dv/dx,
// du/dy, dv/dy), which OpenImageIO's TextureSystem takes to pick mip levels and filter
// anisotropically. Without them a distant textured floor is point-sampled and shimmers.
//
// Camera rays carry exact differentials: the change of direction to the next pixel's ray, the
// offset ray meeting the hit's tangent plane. With n samples a pixel the offsets are scaled by
// max(1/8, 1/sqrt(n)), as pbrt-v4 does: the samples average the rest.
//
// After a reflection or refraction the differential is approximated by a ray cone (Amanatides
// 1984; Akenine-Moeller et al. 2019, "Texture Level of Detail Strategies for Real-Time Ray
// Tracing"): a circle across the ray whose radius is the camera footprint's at the bounce and
// grows by the camera's pixel angle per unit of distance, so its width follows the length of
// the whole path. That is exact for flat mirrors; the curvature of a mirror or a lens, which
// narrows or widens the pencil of rays, is not followed (a convex mirror's reflection is filtered
// less than it should be), and glossy lobes do not widen it (their jittered rays average).
// A cone's lookups take fewer probes along the footprint than a camera ray's (image/
// texture_files.cpp, kConeProbes): a surface seen at a very grazing angle in a mirror blurs a
// little more across, for a cheaper lookup.
#pragma once

#include "core/vec3.h"
#include "geometry/primitives.h"
#include "render/surface.h"

namespace rt {

// The offset rays of pbrt's RayDifferential as differences to the main ray: where the ray of the
// next pixel over (x) or down (y) starts and how its direction differs. All zero: no footprint,
// textures are read unfiltered.
struct RayDifferential {
    Vec3 originX, directionX, originY, directionY;
    // A cone (after a bounce), round across the ray: its lookups take fewer probes (TexCoord::isotropic).
    bool isotropic = false;
    constexpr bool operator==(const RayDifferential&) const = default;

    // A cone around the unit direction d: radius `radius` at the origin, growing by `spread` per unit distance.
    static RayDifferential cone(const Vec3& d, Real radius, Real spread);
    // The larger offset across the ray at distance t: the radius of the cone a bounce passes on.
    Real radiusAt(Real t) const;
    // dp/dx and dp/dy on the plane of unit normal n through the hit at distance t along unit direction d.
    void footprintAt(const Vec3& d, Real t, const Vec3& n, Vec3& dpdx, Vec3& dpdy) const;
};

// Sets s.dudx, s.dvdx, s.dudy and s.dvdy for the hit of a ray (unit direction d, differential
// `diff`) on primitives[hit.prim]: the texture coordinates' change across the footprint, by
// least squares on the triangle's dP/du and dP/dv (pbrt-v4's SurfaceInteraction::
// ComputeDifferentials). No change for a primitive without texture coordinates.
void setUvDerivatives(const Primitives& primitives, const Vec3& d, const Hit& hit, const RayDifferential& diff,
                      SurfacePoint& s);

}  // namespace rt
