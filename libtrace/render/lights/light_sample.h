// What a light sends to a surface point, before the surface's cosine and shadows: the
// direction towards it, how far it is, and the colour that arrives after the distance falloff
// and the spot cone. Thesis point lights (no falloff) arrive with their colour unchanged.
#pragma once

#include "core/color.h"
#include "core/vec3.h"
#include "scene/light.h"

namespace rt {

struct LightIncidence {
    Vec3 toLight;   // unit, from the point towards the light
    Real distance;  // to the light's centre; kInfinity for a directional light
    Color color;    // arriving at the point; black when the point is outside a spot's cone or the range
};

LightIncidence lightIncidence(const Light& light, const Vec3& point);

// KHR_lights_punctual's recommended falloff: max(min(1 - (d / range)^4, 1), 0) / d^2; range 0
// is infinite (pure inverse square).
Real inverseSquareFalloff(Real distance, Real range);

// KHR_lights_punctual's reference spot cone: the cosine between the spot's axis and the
// direction to the point, mapped linearly from cos(outer) (0) to cos(inner) (1), clamped and squared.
Real spotCone(const Light& light, Real cosineToAxis);

}  // namespace rt
