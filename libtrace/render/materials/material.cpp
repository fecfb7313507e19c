#include "render/materials/material.h"

#include <algorithm>
#include <optional>

namespace rt {

Color surfaceColor(const ShadingContext& context, const Material& m, const SurfacePoint& s) {
    const Color c = m.color * s.tint;
    return m.colorTexture ? c * textureColor(context, *m.colorTexture, s) : c;
}

Color surfaceEmission(const ShadingContext& context, const Material& m, const SurfacePoint& s) {
    // Under a black factor the texture cannot matter: not read.
    if (!m.emission.texture || m.emission.color == Color{}) return m.emission.color;
    return m.emission.color * textureColor(context, *m.emission.texture, s);
}

float transmissionAt(const ShadingContext& context, const Material& m, const SurfacePoint& s) {
    const float weight = m.transmission.weight;
    if (!m.transmission.texture || !(weight > 0)) return weight;
    return std::clamp(weight * textureData(context, *m.transmission.texture, s).r, 0.0f, 1.0f);
}

float glossySpread(const ShadingContext& context, const Material& m, const SurfacePoint& s) {
    if (!m.pbr.texture || !m.pbr.factors || !context.images) return m.phong.spread;
    const float roughness = m.pbr.factors->roughness * textureData(context, *m.pbr.texture, s).g;
    return roughness * roughness;
}

MetallicRoughness metallicRoughnessAt(const ShadingContext& context, const Material& m, const SurfacePoint& s) {
    MetallicRoughness f = metallicRoughnessOf(m);
    if (m.pbr.texture) {
        const Color t = textureData(context, *m.pbr.texture, s);
        f.metallic = std::clamp(f.metallic * t.b, 0.0f, 1.0f);
        f.roughness = std::clamp(f.roughness * t.g, 0.0f, 1.0f);
    }
    return f;
}

namespace {

// The image texture giving the material's alpha, if any; `mask` says how it is read.
std::optional<std::uint32_t> alphaImage(const ShadingContext& context, const Material& m, bool& mask) {
    if (!m.opacity.texture || !context.images ||
        context.scene.textures[*m.opacity.texture].kind != Texture::Kind::Image)
        return {};
    mask = m.opacity.texture != m.colorTexture;
    return m.opacity.texture;
}

}  // namespace

float materialAlpha(const ShadingContext& context, const Material& m, Real u, Real v) {
    bool mask = false;
    const std::optional<std::uint32_t> image = alphaImage(context, m, mask);
    if (!image) return m.opacity.alpha;
    const TexCoord at = context.images->uvTransform(*image)(u, v);
    return m.opacity.alpha * context.images->alpha(*image, at.s, at.t, mask);
}

bool cutsOut(const ShadingContext& context, const Material& m) {
    if (!m.opacity.cutoff || !(*m.opacity.cutoff > 0)) return false;
    if (m.opacity.alpha < *m.opacity.cutoff) return true;
    bool mask = false;
    const std::optional<std::uint32_t> image = alphaImage(context, m, mask);
    return image && context.images->hasAlpha(*image, mask);
}

}  // namespace rt
