// The lights of a scene (docs/scene-format.md, <light>). The thesis has point lights that do
// not fall off with distance (thesis 2.1.3): still the default. rt extension: directional and
// spot lights, and the inverse-square falloff with an optional `range` cut-off as glTF's
// KHR_lights_punctual defines them, so that imported lights keep their meaning.
#pragma once

#include "core/color.h"
#include "core/names.h"
#include "core/vec3.h"

namespace rt {

struct Light {
    enum class Type { Point, Directional, Spot };
    enum class Falloff { None, InverseSquare };

    Vec3 position;         // point and spot
    Color color{1, 1, 1};  // no falloff: the irradiance it gives; inverse-square: the irradiance at distance 1
    Real size = 0;         // point and spot: radius of the disc distributed ray tracing samples for soft shadows
    Type type = Type::Point;
    Vec3 direction{0, 0, -1};  // directional and spot: where the light shines, unit length
    Falloff falloff = Falloff::None;
    Real range = 0;  // inverse-square only: beyond it the light is off (KHR's smooth window); 0 is infinite
    // Spot: full brightness inside the inner cone, none outside the outer one (angles from the
    // direction, degrees; KHR_lights_punctual's defaults).
    float innerConeDegrees = 0;
    float outerConeDegrees = 45;
    // rt extension: a point light that belongs to the camera rendered, at its origin wherever
    // --look-from, --frame or --orbit put it (Scene::placeHeadlights): the light a model without
    // lights gets. The path tracer leaves it out of a scene with emissive materials, which light
    // it themselves (render/lights/light_distribution.h).
    bool headlight = false;
};

// Their names in the XML (`type`, `falloff`).
inline constexpr NamedValues<Light::Type, 3> kLightTypeNames{
    {{"point", Light::Type::Point}, {"directional", Light::Type::Directional}, {"spot", Light::Type::Spot}}};
// Their names on rt-render's --light: "sun" is Blender's (and glTF viewers') name for a directional light.
inline constexpr NamedValues<Light::Type, 3> kLightOptionNames{
    {{"point", Light::Type::Point}, {"spot", Light::Type::Spot}, {"sun", Light::Type::Directional}}};
inline constexpr NamedValues<Light::Falloff, 2> kLightFalloffNames{
    {{"none", Light::Falloff::None}, {"inverse_square", Light::Falloff::InverseSquare}}};

}  // namespace rt
