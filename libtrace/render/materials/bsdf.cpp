#include "render/materials/bsdf.h"

#include <algorithm>

#include "render/materials/material.h"

namespace rt {

namespace {

// The opaque part: the metallic-roughness BRDF, under the material's clear coat if it has one.
Bsdf opaqueBsdf(const Material& m, const Color& base, const MetallicRoughness& factors) {
    if (m.clearcoat.weight > 0)
        return Bsdf(ClearcoatBsdf(PbrBsdf(base, factors), m.clearcoat.weight, m.clearcoat.roughness));
    return Bsdf(PbrBsdf(base, factors));
}

}  // namespace

Bsdf bsdfAt(const ShadingContext& context, const Material& m, const SurfacePoint& s, Real& lobe) {
    const Color base = surfaceColor(context, m, s);
    const MetallicRoughness factors = metallicRoughnessAt(context, m, s);
    const float glass = transmissionAt(context, m, s);
    if (!(glass > 0)) return opaqueBsdf(m, base, factors);
    if (lobe < glass) {
        lobe /= glass;
        return Bsdf(DielectricBsdf(m.transmission, factors.roughness, s.frontFace));
    }
    lobe = (lobe - glass) / (1 - glass);
    // the opaque part's own metallic share: m of the whole is m / (1 - glass) of what is left
    MetallicRoughness opaque = factors;
    opaque.metallic = std::min(1.0f, factors.metallic / (1 - glass));
    return opaqueBsdf(m, base, opaque);
}

}  // namespace rt
