#include "io/punctual_light.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rt {

Light placeLight(const PunctualLight& in, const Transform& node, double unitScale, const std::string& what) {
    Light light;
    light.type = in.type;
    light.color = in.color;
    // Each type is checked for what it has: a point light no direction (Assimp's omni lights
    // come with a zero one), a directional light no position.
    if (in.type != Light::Type::Directional) {
        light.position = node.point(in.position);
        if (!isFinite(light.position)) throw InputError(what + " has a NaN or infinite position");
    }
    if (in.type != Light::Type::Point) {
        const Vec3 direction = node.vector(in.direction);
        if (!isFinite(direction) || !(length(direction) > 0))
            throw InputError(what + " has a NaN, infinite or zero direction");
        light.direction = normalize(direction);
    }
    if (!isFinite(in.color) || in.color.r < 0 || in.color.g < 0 || in.color.b < 0)
        throw InputError(what + " has a negative or non-finite colour or intensity");
    if (in.type != Light::Type::Directional && in.inverseSquare) {
        light.falloff = Light::Falloff::InverseSquare;
        light.color *= float(unitScale * unitScale);
        light.range = Real(in.range * unitScale);
    }
    if (!(std::max({light.color.r, light.color.g, light.color.b}) <= kMaxColorValue))
        throw InputError(what + ": its colour times its intensity is beyond 1e15");
    if (in.type == Light::Type::Spot) {
        if (!(0 <= in.innerConeRadians && in.innerConeRadians <= in.outerConeRadians &&
              in.outerConeRadians <= kPi / 2 + 1e-6))
            throw InputError(what + ": the spot cone needs 0 <= inner <= outer <= pi/2");
        light.innerConeDegrees = float(in.innerConeRadians * 180 / kPi);
        light.outerConeDegrees = float(std::min(in.outerConeRadians * 180 / kPi, 90.0));
    }
    return light;
}

}  // namespace rt
