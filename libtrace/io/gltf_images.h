// Images a glTF file holds itself, in a bufferView (a .glb's binary chunk, usually) or as a
// data: URI, as the encoded bytes rt keeps for a texture (Texture::embedded): rt-convert saves
// them as files beside the scene, rt-render reads them from memory (docs/conversion.md).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Image;
}  // namespace tinygltf

namespace rt {

using ImageBytes = std::shared_ptr<const std::vector<std::uint8_t>>;

// tinygltf's image callback: a data: URI's bytes (decoded from base64 by tinygltf) are kept
// encoded (Image::as_is); nothing is decoded, and other images are left for embeddedImage().
bool keepDataUriImage(tinygltf::Image* image, int index, std::string* err, std::string* warn, int width, int height,
                      const unsigned char* bytes, int size, void* user);

// The encoded bytes of image `index` when the file embeds it, null when the image is a file
// of its own (a uri). Throws rt::InputError "file: ..." for a bufferView outside its buffer.
ImageBytes embeddedImage(const tinygltf::Model& gltf, int index, const std::string& file);

// The file name to save an embedded image under: its name (or "image<index>"), made safe for
// file systems, with the extension of its MIME type or, failing that, of its first bytes.
std::string embeddedImageFile(const tinygltf::Image& image, int index, const std::vector<std::uint8_t>& bytes);

}  // namespace rt
