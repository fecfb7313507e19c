#include "render/texture.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace rt {

namespace {

// The solid checker: cubes of side `size` alternate colorA and colorB. The point is taken a
// little inside the surface, so that a face lying on a cube boundary (a floor at y = 0) shows
// one colour, not noise.
Color checker(const Texture& t, const SurfacePoint& s) {
    const Vec3 p = (s.point - s.geometricNormal * Real(t.size * 1e-3)) / Real(t.size);
    const long long cell = (long long)std::floor(p.x) + (long long)std::floor(p.y) + (long long)std::floor(p.z);
    return cell % 2 == 0 ? t.colorA : t.colorB;
}

}  // namespace

UvTransform::UvTransform(const Texture& t)
    : scale_(t.scale), offset_(t.offset), cos_(std::cos(t.rotation)), sin_(std::sin(t.rotation)) {}

std::array<float, 2> UvTransform::linear(float u, float v) const {
    const float su = u * scale_[0], sv = v * scale_[1];
    return {cos_ * su + sin_ * sv, -sin_ * su + cos_ * sv};
}

TexCoord UvTransform::operator()(Real u, Real v) const {
    const std::array<float, 2> st = linear(float(u), float(v));
    return {st[0] + offset_[0], st[1] + offset_[1]};
}

TexCoord UvTransform::operator()(const SurfacePoint& s) const {
    TexCoord c = (*this)(s.u, s.v);
    const std::array<float, 2> dx = linear(s.dudx, s.dvdx), dy = linear(s.dudy, s.dvdy);
    c.dsdx = dx[0];
    c.dtdx = dx[1];
    c.dsdy = dy[0];
    c.dtdy = dy[1];
    c.isotropic = s.isotropic;
    return c;
}

ImageTextures::ImageTextures(const Scene& scene) : transforms_(scene.textures.begin(), scene.textures.end()) {}

namespace {

// Texture `index` at the surface point: a checker evaluated here, an image through `read`
// (ImageTextures::lookup or ::data) at the transformed coordinates; white without lookups.
template <class Read>
Color textureAt(const Scene& scene, std::uint32_t index, const SurfacePoint& s, const ImageTextures* images,
                Read read) {
    const Texture& t = scene.textures[index];
    if (t.kind == Texture::Kind::Checker) return checker(t, s);
    if (!images) return {1, 1, 1};
    return (images->*read)(index, images->uvTransform(index)(s));
}

}  // namespace

Color textureColor(const Scene& scene, std::uint32_t index, const SurfacePoint& s, const ImageTextures* images) {
    return textureAt(scene, index, s, images, &ImageTextures::lookup);
}

Color textureData(const Scene& scene, std::uint32_t index, const SurfacePoint& s, const ImageTextures* images) {
    return textureAt(scene, index, s, images, &ImageTextures::data);
}

Color surfaceColor(const Scene& scene, const Material& m, const SurfacePoint& s, const ImageTextures* images) {
    const Color c = m.color * s.tint;
    return m.colorTexture ? c * textureColor(scene, *m.colorTexture, s, images) : c;
}

Color surfaceEmission(const Scene& scene, const Material& m, const SurfacePoint& s, const ImageTextures* images) {
    // Under a black factor the texture cannot matter: not read.
    if (!m.emissionTexture || m.emission == Color{}) return m.emission;
    return m.emission * textureColor(scene, *m.emissionTexture, s, images);
}

float transmissionAt(const Scene& scene, const Material& m, const SurfacePoint& s, const ImageTextures* images) {
    const float weight = m.transmission.weight;
    if (!m.transmissionTexture || !(weight > 0)) return weight;
    return std::clamp(weight * textureData(scene, *m.transmissionTexture, s, images).r, 0.0f, 1.0f);
}

float glossySpread(const Scene& scene, const Material& m, const SurfacePoint& s, const ImageTextures* images) {
    if (!m.metallicRoughnessTexture || !m.metallicRoughness || !images) return m.spread;
    const float roughness =
        m.metallicRoughness->roughness * textureData(scene, *m.metallicRoughnessTexture, s, images).g;
    return roughness * roughness;
}

namespace {

// The image texture giving the material's alpha, if any; `mask` says how it is read.
std::optional<std::uint32_t> alphaImage(const Scene& scene, const Material& m, const ImageTextures* images,
                                        bool& mask) {
    if (!m.alphaTexture || !images || scene.textures[*m.alphaTexture].kind != Texture::Kind::Image) return {};
    mask = m.alphaTexture != m.colorTexture;
    return m.alphaTexture;
}

}  // namespace

float materialAlpha(const Scene& scene, const Material& m, Real u, Real v, const ImageTextures* images) {
    bool mask = false;
    const std::optional<std::uint32_t> image = alphaImage(scene, m, images, mask);
    if (!image) return m.alpha;
    const TexCoord at = images->uvTransform(*image)(u, v);
    return m.alpha * images->alpha(*image, at.s, at.t, mask);
}

bool cutsOut(const Scene& scene, const Material& m, const ImageTextures* images) {
    if (!m.alphaCutoff || !(*m.alphaCutoff > 0)) return false;
    if (m.alpha < *m.alphaCutoff) return true;
    bool mask = false;
    const std::optional<std::uint32_t> image = alphaImage(scene, m, images, mask);
    return image && images->hasAlpha(*image, mask);
}

}  // namespace rt
