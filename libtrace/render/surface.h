// What shading needs to know about a hit: the geometric normal for ray offsets and side
// decisions, the shading normal (interpolated vertex normals, pbrt's "shading geometry") for
// lighting and mirror directions, where shadow rays start, and the vertex colour and texture
// coordinates. Without vertex data the shading normal is the geometric one and nothing moves,
// so the thesis's scenes shade exactly as before.
#pragma once

#include "core/color.h"
#include "core/ray.h"
#include "geometry/primitives.h"

namespace rt {

struct SurfacePoint {
    Vec3 point;
    Vec3 geometricNormal;   // unit, facing the incoming ray
    bool frontFace = true;  // the ray hit the side the primitive's normal faces (winding, outside)
    Vec3 shadingNormal;     // unit, on the side geometricNormal faces
    Vec3 shadowOrigin;      // where shadow rays leave from, before the offset along geometricNormal
    Color tint{1, 1, 1};    // the vertex colour
    Real u = 0, v = 0;      // texture coordinates
    // Their change from one pixel to the next (render/ray_differential.h); zero: read unfiltered.
    float dudx = 0, dvdx = 0, dudy = 0, dvdy = 0;
    bool isotropic = false;  // the footprint is a ray cone's (RayDifferential::isotropic)
};

// How far secondary rays start off a surface, scaled to the size of the scene: the error of a
// computed hit point grows with the magnitude of its coordinates, so a fixed offset is too
// small for a city and too large for a teapot.
Real secondaryRayOffset(const Primitives& primitives);

// The surface at `hit`, a hit of `ray` on primitives[hit.prim].
SurfacePoint surfaceAt(const Primitives& primitives, const Ray& ray, const Hit& hit);

// The point p of a triangle with barycentric weights b, moved onto the smooth surface its
// vertex normals describe: the mean of p projected onto each vertex's tangent plane, where p
// lies below it (Hanika 2021, "Hacking the Shadow Terminator", Ray Tracing Gems II ch. 4).
// Shadow rays from there do not hit the flat facets of a coarse mesh near the terminator.
// The normals must face the side p is seen from.
// b1 and b2 are the weights of p1 and p2, as Hit::u and Hit::v.
Vec3 offsetToSmoothSurface(const Vec3& p, const Triangle& tri, const Vec3 (&normals)[3], Real b1, Real b2);

// The shading normal n turned towards the geometric normal ng (unit, on the viewer's side) just
// enough that the mirror direction of `toViewer` about it leaves the surface, at least as steeply
// as min(0.9 cos, 0.01) for the viewer's cos against ng; n itself when it does already, as a flat
// surface's (n = ng) always does. A normal map's steep slopes otherwise mirror the view into the
// surface, where a path finds nothing and a mirror shows black rings. The idea, the threshold and
// the plane of the turn are Blender Cycles' (ensure_valid_reflection in its kernel); the angle of
// the turn is solved in closed form here.
Vec3 keepReflectionAbove(const Vec3& n, const Vec3& ng, const Vec3& toViewer);

}  // namespace rt
