#include "render/texture.h"

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

std::array<float, 2> transformUv(const Texture& t, Real u, Real v) {
    const float su = float(u) * t.scale[0], sv = float(v) * t.scale[1];
    const float c = std::cos(t.rotation), s = std::sin(t.rotation);
    return {c * su + s * sv + t.offset[0], -s * su + c * sv + t.offset[1]};
}

Color textureColor(const Scene& scene, std::uint32_t index, const SurfacePoint& s, const ImageTextures* images) {
    const Texture& t = scene.textures[index];
    if (t.kind == Texture::Kind::Checker) return checker(t, s);
    if (!images) return {1, 1, 1};
    const std::array<float, 2> uv = transformUv(t, s.u, s.v);
    return images->lookup(index, uv[0], uv[1]);
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
    const std::array<float, 2> uv = transformUv(scene.textures[*image], u, v);
    return m.alpha * images->alpha(*image, uv[0], uv[1], mask);
}

bool cutsOut(const Scene& scene, const Material& m, const ImageTextures* images) {
    if (!m.alphaCutoff || !(*m.alphaCutoff > 0)) return false;
    if (m.alpha < *m.alphaCutoff) return true;
    bool mask = false;
    const std::optional<std::uint32_t> image = alphaImage(scene, m, images, mask);
    return image && images->hasAlpha(*image, mask);
}

}  // namespace rt
