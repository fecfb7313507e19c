// Image textures read through OpenImageIO's TextureSystem: any format it reads, mip-mapped on
// the fly, cached (memory bounded by the cache size for tiled, MIP-mapped files; untiled ones,
// PNG and JPEG, are held a whole level at a time: docs/benchmarks.md) and thread-safe. 8- and 16-bit images are taken
// as sRGB-encoded, as glTF's base colour and emissive textures are, and decoded to linear; float images (EXR, HDR) as
// linear.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "render/texture.h"
#include "scene/scene.h"

namespace OIIO_NAMESPACE_FORWARD {}

namespace rt {

class TextureFiles : public ImageTextures {
public:
    // Opens the scene's image textures. One that cannot be read is white (the material's
    // colour alone) and named in `warnings`: a missing texture does not stop a render.
    TextureFiles(const Scene& scene, std::vector<std::string>& warnings, float cacheMegabytes = 256);
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
