// Image textures as rt-render reads them (image/texture_files.h): OpenImageIO opens the file and
// decodes it (PNG, JPEG, EXR, TIFF, ...: the reader is chosen by the extension, then by the
// bytes) into rt's MIP map, looked up as colour, data and alpha. The input's first byte picks
// the file's extension; the rest is the file.
#include <array>

#include "fuzz_input.h"
#include "image/texture_files.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static constexpr std::array<const char*, 8> kExtensions{".png", ".jpg", ".exr", ".tif",
                                                            ".tga", ".hdr", ".bmp", ".webp"};
    if (size == 0) return 0;
    rt::Scene scene;
    rt::Texture& texture = scene.textures.emplace_back();
    texture.name = "fuzz";
    texture.path = rt::fuzz::writeInputFile(data + 1, size - 1, std::string("texture") + kExtensions[data[0] % 8]);
    // An unreadable image is white and a warning; one image/image_header.h refuses, an input error.
    return rt::fuzz::expectInputErrorOnly([&] {
        std::vector<std::string> warnings;
        const rt::TextureFiles textures(scene, warnings, rt::TextureSettings{});
        for (const float st : {0.0f, 0.37f, 0.999f, -2.5f}) {
            textures.lookup(0, rt::TexCoord{st, 1 - st});
            textures.lookup(0, rt::TexCoord{st, st, 0.01f, 0, 0, 0.02f});  // filtered: the MIP levels
            textures.lookup(0, rt::TexCoord{st, st, 1e30f, -1e30f, 0, 0});
            textures.data(0, rt::TexCoord{st, st});
            if (textures.hasAlpha(0, true)) textures.alpha(0, st, 0.5f, true);
        }
    });
}
