// A ray x(t) = origin + t * direction (thesis 2.1.2). Directions are unit length
// wherever rays are made (camera, shadows, reflections); the sphere test relies on it.
#pragma once

#include "core/vec3.h"

namespace rt {

struct Ray {
    Vec3 origin;
    Vec3 direction;
    // A shadow ray, traced from a shaded point towards a light: a hit filter judges which side of
    // a single-sided surface it meets as the light sees it (render/material_filter.h). Only the
    // filter reads it, so rays in scenes without one cost nothing more.
    bool shadow = false;

    constexpr Vec3 at(Real t) const { return origin + direction * t; }
};

// The nearest intersection found so far: distance along the ray, which primitive,
// and its barycentric coordinates (triangles) for later use.
struct Hit {
    Real t = kInfinity;
    std::uint32_t prim = ~0u;
    Real u = 0, v = 0;
};

}  // namespace rt
