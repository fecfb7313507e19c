#include "import/phong_from_pbr.h"

#include <algorithm>

namespace rt {
namespace {

float clamp01(float x) { return std::clamp(x, 0.0f, 1.0f); }
Color clampColor(const Color& c) { return {std::max(c.r, 0.0f), std::max(c.g, 0.0f), std::max(c.b, 0.0f)}; }

}  // namespace

Material phongFromMetallicRoughness(const MetallicRoughness& pbr) {
    const Color base = clampColor(pbr.baseColor);
    const float metallic = clamp01(pbr.metallic);
    const float roughness = clamp01(pbr.roughness);
    const float ior = std::max(pbr.ior, 1.0f);
    const float fresnel = (ior - 1) / (ior + 1);
    const float dielectricF0 =
        clamp01(fresnel * fresnel * std::max(pbr.specularFactor, 0.0f) * luminance(clampColor(pbr.specularColor)));
    const float f0 = clamp01((1 - metallic) * dielectricF0 + metallic * luminance(base));
    const float alpha = std::max(roughness * roughness, 1e-3f);

    Material m;
    m.color = base;
    m.diffuse = 0.9f * (1 - metallic);
    m.specular = f0;
    m.shininess = std::clamp(2 / (alpha * alpha) - 2, 1.0f, 10000.0f);
    m.reflection = f0 * (1 - roughness);
    m.spread = alpha;
    m.metallicRoughness = MetallicRoughnessFactors{metallic, roughness, clamp01(pbr.specularFactor)};
    const float transmission = clamp01(pbr.transmission) * (1 - metallic);
    if (transmission > 0) {
        m.ambient *= 1 - transmission;
        m.diffuse *= 1 - transmission;
        m.reflection *= 1 - transmission;
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

}  // namespace rt
