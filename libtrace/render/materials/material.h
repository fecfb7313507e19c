// What a material (scene/scene.h Material) is at a surface point, for both integrators: its
// colour, emission, transmission, glossy spread, metallic-roughness factors and opacity, each
// with its texture applied. The path tracer turns them into a BSDF (render/materials/bsdf.h);
// the Whitted tracer shades with them and the Phong terms (render/materials/phong.h).
#pragma once

#include <cstdint>

#include "render/surface.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

// The material's colour at the surface point (vertex colour and texture applied), and what it
// emits there (its emission times its emission texture).
Color surfaceColor(const ShadingContext& context, const Material& m, const SurfacePoint& s);
Color surfaceEmission(const ShadingContext& context, const Material& m, const SurfacePoint& s);
// The share of the light the material lets through at s: Transmission::weight times the red
// channel of its transmission texture (read as data), if it has one.
float transmissionAt(const ShadingContext& context, const Material& m, const SurfacePoint& s);
// The sigma of the material's glossy lobe at the surface point, for its reflection and, on glass,
// its transmission: PhongTerms::spread; with a metallic-roughness texture, (roughness times the
// texture's green)^2, the GGX alpha that spread is made from (scene/metallic_roughness.h).
float glossySpread(const ShadingContext& context, const Material& m, const SurfacePoint& s);
// The metallic-roughness factors at s (metallicRoughnessOf, scene/metallic_roughness.h), scaled
// by the metallic-roughness texture if the material has one: its blue channel scales metallic,
// its green roughness.
MetallicRoughness metallicRoughnessAt(const ShadingContext& context, const Material& m, const SurfacePoint& s);
// The opacity of the material at texture coordinates (u, v) (Opacity::alpha times its texture, Material::opacity);
// a checker or no image lookups: alpha alone.
float materialAlpha(const ShadingContext& context, const Material& m, Real u, Real v);
// Whether materialAlpha can be below the material's cut-off anywhere: a cut-out whose texture
// has no alpha and whose factor is above the cut-off is opaque.
bool cutsOut(const ShadingContext& context, const Material& m);

}  // namespace rt
