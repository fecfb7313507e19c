#include "render/lights/light_sample.h"

#include <algorithm>
#include <cmath>

#include "scene/spot_cone.h"

namespace rt {

Real inverseSquareFalloff(Real distance, Real range) {
    const Real inverseSquare = 1 / (distance * distance);
    if (!(range > 0)) return inverseSquare;
    const Real ratio = distance / range;
    return std::clamp(1 - ratio * ratio * ratio * ratio, Real(0), Real(1)) * inverseSquare;
}

Real spotCone(const Light& light, Real cosineToAxis) {
    const SpotCone cone = spotConeOf(light);
    const Real scale = 1 / std::max(Real(0.001), cone.cosInner - cone.cosOuter);
    const Real a = std::clamp((cosineToAxis - cone.cosOuter) * scale, Real(0), Real(1));
    return a * a;
}

LightIncidence lightIncidence(const Light& light, const Vec3& point) {
    if (light.type == Light::Type::Directional) return {-light.direction, kInfinity, light.color};
    const Vec3 d = light.position - point;
    const Real distance = length(d);
    LightIncidence in{d / distance, distance, light.color};  // d / |d| is normalize(d), bit for bit
    if (light.falloff == Light::Falloff::InverseSquare)
        in.color *= float(inverseSquareFalloff(in.distance, light.range));
    if (light.type == Light::Type::Spot) in.color *= float(spotCone(light, dot(light.direction, -in.toLight)));
    return in;
}

}  // namespace rt
