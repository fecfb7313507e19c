#include "scene/metallic_roughness.h"

#include <algorithm>
#include <cmath>

#include "scene/scene.h"

namespace rt {
namespace {

float clamp01(float x) { return std::clamp(x, 0.0f, 1.0f); }
Color clampColor(const Color& c) { return {std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f)}; }

}  // namespace

Material phongFromMetallicRoughness(const PbrMaterialFactors& pbr) {
    const Color base = clampColor(pbr.baseColor);
    const float metallic = clamp01(pbr.factors.metallic);
    const float roughness = clamp01(pbr.factors.roughness);
    const float ior = std::max(pbr.ior, 1.0f);
    const float fresnel = (ior - 1) / (ior + 1);
    const float dielectricF0 =
        clamp01(fresnel * fresnel * std::max(pbr.factors.specular, 0.0f) * luminance(clampColor(pbr.specularColor)));
    const float metalF0 = luminance(base);
    const float f0 = clamp01((1 - metallic) * dielectricF0 + metallic * metalF0);
    const float alpha = std::max(roughness * roughness, 1e-3f);

    // A metal's lobe of width alpha: Phong's highlight, (R.V)^n, ends 90 degrees from the mirror
    // direction and has the light's colour, so a rough metal drawn as a highlight alone is black
    // but for a white patch (the glTF default, metallic 1 and roughness 1, under a point light).
    // The share alpha of the metal's reflectance goes to the diffuse term, tinted by its colour: a
    // fully rough metal is diffuse in its colour, as its microfacet lobe is nearly uniform; a
    // polished one keeps the highlight and the mirror.
    const float roughMetal = metallic * roughness * roughness;
    Material m;
    m.color = base;
    m.phong.diffuse = 0.9f * (1 - metallic) + roughMetal;
    m.phong.specular = clamp01(f0 - roughMetal * metalF0);
    m.phong.shininess = std::clamp(2 / (alpha * alpha) - 2, 1.0f, 10000.0f);
    m.phong.reflection = f0 * (1 - roughness);
    m.phong.spread = alpha;
    m.pbr.factors = MetallicRoughness{metallic, roughness, clamp01(pbr.factors.specular)};
    const float transmission = clamp01(pbr.transmission) * (1 - metallic);
    if (transmission > 0) {
        m.phong.ambient *= 1 - transmission;
        m.phong.diffuse *= 1 - transmission;
        m.phong.reflection *= 1 - transmission;
        m.transmission = {.weight = transmission,
                          .color = base,
                          .ior = ior,
                          .thin = !(pbr.thickness > 0),
                          .attenuationColor = clampColor(pbr.attenuationColor),
                          .attenuationDistance = pbr.attenuationDistance > 0 ? pbr.attenuationDistance
                                                                             : Transmission{}.attenuationDistance};
    }
    return m;
}

MetallicRoughness metallicRoughnessOf(const Material& m) {
    if (m.pbr.factors) return *m.pbr.factors;
    const float alpha =
        m.phong.reflection > 0 ? m.phong.spread : std::sqrt(2 / (std::max(m.phong.shininess, 0.0f) + 2));
    return {clamp01(m.phong.reflection), clamp01(std::sqrt(alpha)), m.phong.specular > 0 ? 1.0f : 0.0f};
}

}  // namespace rt
