// The glTF metallic-roughness material, and the one mapping between it and the thesis's Phong
// material (thesis 2.1.3, 3.3.2), in both directions: importers make a Phong material from glTF's
// factors (phongFromMetallicRoughness), and the path tracer, which renders the factors, takes
// them back from a thesis material that has none (metallicRoughnessOf). docs/conversion.md writes
// the mapping out; docs/path-tracing.md the rule for thesis materials.
//
// Glossy lobes are Trowbridge-Reitz (GGX) lobes of width alpha = roughness^2 throughout; the Phong
// exponent n stands for the lobe of the same width, alpha = sqrt(2 / (n + 2)) (Walter et al. 2007,
// "Microfacet Models for Refraction", section 5.2), and the spread of distributed ray tracing is
// alpha in radians.
//
// From glTF to Phong:
//   F0_dielectric = ((ior - 1) / (ior + 1))^2 * specularFactor * lum(specularColorFactor)
//   F0            = (1 - metallic) * F0_dielectric + metallic * lum(baseColor)
//   colour        = baseColor (linear RGB, as glTF stores factors)
//   diffuse       = 0.9 * (1 - metallic)          metals have no diffuse term
//   specular      = F0                            Phong k_s: the highlight's peak reflectance
//   shininess     = 2 / alpha^2 - 2, clamped to [1, 10000]
//   reflection    = F0 * (1 - roughness)          rough surfaces give no sharp mirror image
//   spread        = alpha (radians)               the glossy lobe of distributed ray tracing
// The factors themselves are kept too (PbrTerms::factors, Material::pbr) for the path tracer.
// KHR_materials_transmission and _volume: the dielectric part lets t = transmission * (1 - metallic)
// through, tinted by baseColor, refracted by ior (straight on when thin-walled, thicknessFactor 0
// or no volume), absorbed by attenuationColor at attenuationDistance. That light is no longer
// scattered: ambient, diffuse and reflection are multiplied by (1 - t), and the renderer's
// Fresnel term reflects the glass's share.
//
// From Phong to glTF (a thesis material):
//   metallic  = reflection                        a mirror is a metal of the material's colour
//   roughness = sqrt(alpha), alpha = spread for a mirror, else the Phong exponent's lobe
//   specular  = 1 if k_s > 0, else 0              no specular layer without a highlight
#pragma once

#include <limits>

#include "core/color.h"

namespace rt {

struct Material;

// The factors of glTF's metallic-roughness BRDF (render/materials/pbr_bsdf.h), each 0-1; the base
// colour is the material's colour. The defaults are a rough dielectric.
struct MetallicRoughness {
    float metallic = 0;
    float roughness = 1;
    float specular = 1;  // KHR_materials_specular's specularFactor: 0 leaves a pure Lambertian base
};

// A glTF material as an importer reads it: the core factors and those of the extensions that
// shape the Phong mapping. The defaults are glTF's.
struct PbrMaterialFactors {
    Color baseColor{1, 1, 1};
    MetallicRoughness factors{.metallic = 1};
    float ior = 1.5f;              // KHR_materials_ior
    Color specularColor{1, 1, 1};  // KHR_materials_specular
    float transmission = 0;        // KHR_materials_transmission
    float thickness = 0;           // KHR_materials_volume: 0 (or no volume) is thin-walled
    Color attenuationColor{1, 1, 1};
    float attenuationDistance = std::numeric_limits<float>::infinity();
};

// Throws nothing: inputs are clamped to their valid ranges (colours >= 0, metallic and
// roughness and transmission to [0, 1], ior >= 1). Non-finite inputs must be rejected by the caller.
Material phongFromMetallicRoughness(const PbrMaterialFactors& pbr);

// The factors the path tracer renders material m with: its own, or those of its Phong terms.
MetallicRoughness metallicRoughnessOf(const Material& m);

}  // namespace rt
