#include "io/gltf_images.h"

#include <tiny_gltf.h>

#include <filesystem>

#include "core/error.h"
#include "scene/unique_names.h"

namespace rt {

namespace {

// The formats glTF and its extensions name (image/png, image/jpeg; EXT_texture_webp), by MIME
// type and by signature.
struct ImageFormat {
    const char* mime;
    const char* extension;
    std::string_view signature;
};
constexpr ImageFormat kFormats[] = {{"image/png", ".png", "\x89PNG"},
                                    {"image/jpeg", ".jpg", "\xFF\xD8\xFF"},
                                    {"image/webp", ".webp", "RIFF"},
                                    {"image/bmp", ".bmp", "BM"},
                                    {"image/gif", ".gif", "GIF8"}};

std::string extensionOf(const std::string& mime, const std::vector<std::uint8_t>& bytes) {
    for (const ImageFormat& f : kFormats)
        if (mime == f.mime) return f.extension;
    const std::string_view head(reinterpret_cast<const char*>(bytes.data()), std::min<std::size_t>(bytes.size(), 8));
    for (const ImageFormat& f : kFormats)
        if (head.starts_with(f.signature)) return f.extension;
    return ".png";  // unknown: OpenImageIO will say it cannot read it
}

}  // namespace

bool keepDataUriImage(tinygltf::Image* image, int, std::string*, std::string*, int, int, const unsigned char* bytes,
                      int size, void*) {
    if (image->bufferView < 0 && image->uri.empty() && bytes && size > 0) {
        image->image.assign(bytes, bytes + size);
        image->as_is = true;
    }
    return true;
}

ImageBytes embeddedImage(const tinygltf::Model& gltf, int index, const std::string& file) {
    const tinygltf::Image& image = gltf.images.at(std::size_t(index));
    if (image.as_is && !image.image.empty()) return std::make_shared<std::vector<std::uint8_t>>(image.image);
    if (image.bufferView < 0) return nullptr;
    const std::string what =
        file + ": image " + std::to_string(index) + " bufferView " + std::to_string(image.bufferView);
    if (std::size_t(image.bufferView) >= gltf.bufferViews.size()) throw InputError(what + " does not exist");
    const tinygltf::BufferView& view = gltf.bufferViews[std::size_t(image.bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= gltf.buffers.size())
        throw InputError(what + " names buffer " + std::to_string(view.buffer) + ", which does not exist");
    const std::vector<unsigned char>& data = gltf.buffers[std::size_t(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        throw InputError(what + " lies outside its buffer");
    const auto begin = data.begin() + std::ptrdiff_t(view.byteOffset);
    return std::make_shared<std::vector<std::uint8_t>>(begin, begin + std::ptrdiff_t(view.byteLength));
}

std::string embeddedImageFile(const tinygltf::Image& image, int index, const std::vector<std::uint8_t>& bytes) {
    const std::string stem = std::filesystem::path(image.name).stem().string();
    return safeName(stem.empty() ? "image" + std::to_string(index) : stem) + extensionOf(image.mimeType, bytes);
}

}  // namespace rt
