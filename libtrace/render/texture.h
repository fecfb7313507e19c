// Colours from the scene's textures (scene/scene.h Texture). A checker is evaluated here;
// image textures are looked up through ImageTextures, which image/ implements with
// OpenImageIO's TextureSystem, so that the renderer needs no image library. Without one (unit
// tests, rt-inspect) an image texture gives white: the material's own colour.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "render/surface.h"
#include "scene/scene.h"

namespace rt {

// Where a texture is read: coordinates (s, t) and their change from one pixel to the next,
// which sets the filter's footprint (all zero: the finest level, bilinear).
struct TexCoord {
    float s = 0, t = 0;
    float dsdx = 0, dtdx = 0, dsdy = 0, dtdy = 0;
    bool isotropic = false;  // a ray cone's footprint (RayDifferential::isotropic): fewer probes
};

// A texture's coordinate transform, as KHR_texture_transform defines it: scaled, then rotated,
// then offset. The rotation's cosine and sine are computed once per texture, not per hit.
class UvTransform {
public:
    explicit UvTransform(const Texture& t);
    TexCoord operator()(Real u, Real v) const;
    // The surface point's coordinates with their derivatives, which take the linear part.
    TexCoord operator()(const SurfacePoint& s) const;

private:
    std::array<float, 2> linear(float u, float v) const;  // scaled and rotated

    std::array<float, 2> scale_, offset_;
    float cos_, sin_;
};

class ImageTextures {
public:
    explicit ImageTextures(const Scene& scene);  // takes the transforms of the scene's textures
    virtual ~ImageTextures() = default;
    // Linear RGB of the scene's image texture `index` at `at`, texture coordinates already
    // transformed (uvTransform), filtered over its footprint, with the texture's wrap modes. Thread-safe.
    virtual Color lookup(std::uint32_t index, const TexCoord& at) const = 0;
    // The same values as stored, not colour-decoded (normal maps); (0.5, 0.5, 1), the
    // unperturbed normal, where the image cannot be read. Thread-safe.
    virtual Color data(std::uint32_t index, const TexCoord& at) const = 0;
    // The opacity of image texture `index` at (s, t): its alpha channel; an image without one
    // gives its first channel if `mask` (a greyscale mask, as OBJ's map_d), else 1. Not
    // colour-decoded. Thread-safe.
    virtual float alpha(std::uint32_t index, float s, float t, bool mask) const = 0;
    // Whether alpha(index, ..., mask) can be other than 1: the image has what it reads, and that is
    // not 1 everywhere (a picture of one colour, opaque).
    virtual bool hasAlpha(std::uint32_t index, bool mask) const = 0;
    const UvTransform& uvTransform(std::uint32_t index) const { return transforms_[index]; }

private:
    std::vector<UvTransform> transforms_;
};

// What shading reads besides the material and the surface point: the scene (its textures) and
// the lookups of its image textures (none: an image texture gives white, the material's own
// colour). Both outlive the context; it is passed where a scene and its lookups go together.
// A scene alone converts to a context without lookups, for code that has no images.
struct ShadingContext {
    ShadingContext(const Scene& s, const ImageTextures* i = nullptr) : scene(s), images(i) {}  // NOLINT: implicit
    const Scene& scene;
    const ImageTextures* images;
};

// The colour of texture `index` of the scene at the surface point.
Color textureColor(const ShadingContext& context, std::uint32_t index, const SurfacePoint& s);
// The same for a texture that holds data, not colour (metallic-roughness): values as stored.
Color textureData(const ShadingContext& context, std::uint32_t index, const SurfacePoint& s);

}  // namespace rt
