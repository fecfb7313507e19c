// Lights of imported files as rt lights (docs/conversion.md, Lights): glTF's KHR_lights_punctual
// and Assimp's aiLight describe the same three kinds, point, spot and directional, placed by a
// node. Point and spot lights fall off with the inverse square of the distance, as the files
// define them; directional lights do not.
#pragma once

#include <string>

#include "core/transform.h"
#include "scene/light.h"

namespace rt {

// A light as the file gives it, in the node's space: at the origin, shining along -Z
// (KHR_lights_punctual), or at `position` along `direction` (aiLight).
struct PunctualLight {
    Light::Type type = Light::Type::Point;
    Vec3 position{0, 0, 0};
    Vec3 direction{0, 0, -1};
    Color color{1, 1, 1};         // times the intensity
    double range = 0;             // 0: infinite
    double innerConeRadians = 0;  // spot: from the axis
    double outerConeRadians = kPi / 4;
    bool inverseSquare = true;  // point and spot
};

// Photometric intensities (glTF: candela for point and spot lights, lux for directional ones)
// become radiometric ones at 683 lm/W, the luminous efficacy of 555 nm light (the rule of
// Blender's glTF importer, W = cd * 4 pi / 683): rt's colour of a point or spot light is then
// its intensity in W/sr, of a directional light its irradiance in W/m^2 (docs/conversion.md).
constexpr double kRtPerPhotometricUnit = 1.0 / 683;

// The rt light `node` places. `unitScale` is --scale: distances grow by it, so an
// inverse-square light's intensity grows by its square and the range by it, keeping the
// picture. Throws rt::InputError "file: what ..." for a light rt cannot draw (NaN, a cone
// outside 0 <= inner <= outer <= pi/2).
Light placeLight(const PunctualLight& light, const Transform& node, double unitScale, const std::string& what);

}  // namespace rt
