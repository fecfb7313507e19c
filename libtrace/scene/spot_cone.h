// A spot light's cone in the renderers' terms (scene/light.h keeps the angles in degrees, as the
// scene format and KHR_lights_punctual give them).
#pragma once

#include <algorithm>
#include <cmath>

#include "core/real.h"
#include "scene/light.h"

namespace rt {

// Its angles from the direction in radians, the inner no wider than the outer, and their cosines:
// the one conversion of the degrees, so that
// what a spot sends (render/lights/light_sample.h) and what the light tree and the power sampler
// expect of it (render/lights/light_distribution.h) agree to the bit.
struct SpotCone {
    Real inner = 0;  // full brightness inside
    Real outer = 0;  // none outside
    Real cosInner = 1;
    Real cosOuter = 1;
};

inline SpotCone spotConeOf(const Light& light) {
    constexpr Real kRadiansPerDegree = kPi / 180;
    SpotCone cone;
    cone.inner = Real(std::min(light.innerConeDegrees, light.outerConeDegrees)) * kRadiansPerDegree;
    cone.outer = Real(light.outerConeDegrees) * kRadiansPerDegree;
    cone.cosInner = std::cos(cone.inner);
    cone.cosOuter = std::cos(cone.outer);
    return cone;
}

}  // namespace rt
