// Image textures read through OpenImageIO's TextureSystem: any format it reads, cached and
// thread-safe. Pictures not tiled and MIP-mapped already (PNG, JPEG) are read through tiled,
// MIP-mapped copies made once (image/tiled_textures.h), so that memory stays within the cache
// size; with the tx cache off they are MIP-mapped on the fly and held a whole level at a time
// (docs/benchmarks.md, "Textures"). 8- and 16-bit images are taken
// as sRGB-encoded, as glTF's base colour and emissive textures are, and decoded to linear; float images (EXR, HDR) as
// linear.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "image/tiled_textures.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace OIIO_NAMESPACE_FORWARD {}

namespace rt {

struct TextureCacheSettings {
    float megabytes = 256;        // OpenImageIO's texture cache (rt-render --texture-cache)
    std::string txCache = "off";  // the folder of tiled copies (rt-render --tx-cache); "off": sources as they are
    double txCacheMegabytes = kDefaultTxCacheMegabytes;  // the bound on its size (rt-render --tx-cache-size)
    // Told what is being done before each copy is made ("making a tiled copy of ..."), the
    // seconds a first render of a textured model spends before its tree is built; none: silence.
    std::function<void(const std::string&)> announce{};
};

// What opening the scene's image textures takes in memory at most, from their headers
// (image/image_header.h), for rt-render --max-memory: OpenImageIO's cache (`cache.megabytes`) once
// a scene has an image; with the tx cache, the picture whose copy costs most, read whole while its
// tiled copy is made; without, every picture that is not tiled and MIP-mapped, held whole with its
// MIP levels. Throws rt::InputError for a texture TextureFiles refuses.
std::uint64_t estimateTextureMemory(const Scene& scene, const TextureCacheSettings& cache);

class TextureFiles : public ImageTextures {
public:
    // Opens the scene's image textures, making their tiled copies where needed. One that cannot
    // be read is white (the material's colour alone) and named in `warnings`: a missing texture
    // does not stop a render, nor does a tx cache that cannot be written (a warning).
    TextureFiles(const Scene& scene, std::vector<std::string>& warnings, const TextureCacheSettings& cache = {});
    ~TextureFiles() override;

    Color lookup(std::uint32_t index, const TexCoord& at) const override;
    Color data(std::uint32_t index, const TexCoord& at) const override;
    float alpha(std::uint32_t index, float s, float t, bool mask) const override;
    bool hasAlpha(std::uint32_t index, bool mask) const override;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rt
