#include "render/texture.h"

#include <cmath>

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
Color textureAt(const ShadingContext& context, std::uint32_t index, const SurfacePoint& s, Read read) {
    const Texture& t = context.scene.textures[index];
    if (t.kind == Texture::Kind::Checker) return checker(t, s);
    const ImageTextures* images = context.images;
    if (!images) return {1, 1, 1};
    return (images->*read)(index, images->uvTransform(index)(s));
}

}  // namespace

Color textureColor(const ShadingContext& context, std::uint32_t index, const SurfacePoint& s) {
    return textureAt(context, index, s, &ImageTextures::lookup);
}

Color textureData(const ShadingContext& context, std::uint32_t index, const SurfacePoint& s) {
    return textureAt(context, index, s, &ImageTextures::data);
}

}  // namespace rt
