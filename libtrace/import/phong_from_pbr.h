// The glTF metallic-roughness material (with KHR_materials_specular and KHR_materials_ior)
// mapped onto the thesis's Phong material (thesis 2.1.3, 3.3.2). The mapping, written out
// in docs/conversion.md:
//   F0_dielectric = ((ior - 1) / (ior + 1))^2 * specularFactor * lum(specularColorFactor)
//   F0            = (1 - metallic) * F0_dielectric + metallic * lum(baseColor)
//   colour        = baseColor (linear RGB, as glTF stores factors)
//   diffuse       = 0.9 * (1 - metallic)          metals have no diffuse term
//   specular      = F0                            Phong k_s: the highlight's peak reflectance
//   shininess     = 2 / alpha^2 - 2, alpha = roughness^2, clamped to [1, 10000]
//                   (the Phong exponent equivalent to a Beckmann lobe of width alpha,
//                   Walter et al. 2007, "Microfacet Models for Refraction", section 5.2)
//   reflection    = F0 * (1 - roughness)          rough surfaces give no sharp mirror image
//   spread        = alpha (radians)               the glossy lobe of distributed ray tracing
// The factors themselves are kept too (Material::metallicRoughness) for the path tracer.
// KHR_materials_transmission and _volume: the dielectric part lets t = transmission * (1 - metallic)
// through, tinted by baseColor, refracted by ior (straight on when thin-walled, thicknessFactor 0
// or no volume), absorbed by attenuationColor at attenuationDistance. That light is no longer
// scattered: ambient, diffuse and reflection are multiplied by (1 - t), and the renderer's
// Fresnel term reflects the glass's share.
#pragma once

#include <limits>

#include "core/color.h"
#include "scene/scene.h"

namespace rt {

struct MetallicRoughness {
    Color baseColor{1, 1, 1};
    float metallic = 1;
    float roughness = 1;
    float ior = 1.5f;              // KHR_materials_ior
    float specularFactor = 1;      // KHR_materials_specular
    Color specularColor{1, 1, 1};  // KHR_materials_specular
    float transmission = 0;        // KHR_materials_transmission
    float thickness = 0;           // KHR_materials_volume: 0 (or no volume) is thin-walled
    Color attenuationColor{1, 1, 1};
    float attenuationDistance = std::numeric_limits<float>::infinity();
};

// Throws nothing: inputs are clamped to their valid ranges (colours >= 0, metallic and
// roughness and transmission to [0, 1], ior >= 1). Non-finite inputs must be rejected by the caller.
Material phongFromMetallicRoughness(const MetallicRoughness& pbr);

}  // namespace rt
