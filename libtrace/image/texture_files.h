// Image textures: each picture a scene names is decoded once by OpenImageIO (any format it reads,
// files and pictures embedded in a model), after rt's header check (image/image_header.h), and
// held in memory as rt's own MIP map (image/mip_map.h), which every lookup reads. No file is
// written. 8- and 16-bit pictures are taken as sRGB-encoded, as glTF's base colour and emissive
// textures are, and decoded to linear by lookup(); float pictures (EXR, HDR) as linear.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "image/mip_map.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

struct TextureSettings {
    TextureFilter filter = TextureFilter::Anisotropic;  // rt-render --texture-filter
    // Told what is being done before the pictures are read ("reading 5 texture pictures, 24 MB"),
    // so that a model with large textures does not seem to hang; none: silence.
    std::function<void(const std::string&)> announce{};
};

// What the scene's image textures take in memory at most, from their headers, for rt-render
// --max-memory: every distinct picture's MIP map (its texels as stored, and a third more for the
// coarser levels), and the pictures decoded at once while they are read. Throws rt::InputError
// for a texture TextureFiles refuses.
std::uint64_t estimateTextureMemory(const Scene& scene);

class TextureFiles : public ImageTextures {
public:
    // Reads the scene's pictures, each distinct one once, several at a time (the same MIP maps
    // whatever the number of threads). One that cannot be read is white (the material's colour
    // alone) and named in `warnings`: a missing texture does not stop a render. Throws
    // rt::InputError for a picture the header check refuses.
    TextureFiles(const Scene& scene, std::vector<std::string>& warnings, const TextureSettings& settings = {});
    ~TextureFiles() override;

    Color lookup(std::uint32_t index, const TexCoord& at) const override;
    Color data(std::uint32_t index, const TexCoord& at) const override;
    float alpha(std::uint32_t index, float s, float t, bool mask) const override;
    bool hasAlpha(std::uint32_t index, bool mask) const override;

    // The MIP map texture `index` reads; null for one that cannot be read or is not an image.
    const MipMap* mipMap(std::uint32_t index) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace rt
