// The one check every image a scene names passes before OpenImageIO reads any of its pixels:
// textures of every format (files and pictures embedded in a model) and the environment image
// (rt-render --environment, <environment>). Each limit answers an input found to hang rt-render
// or take gigabytes (docs/robustness.md, "Limits"):
//   - a file must be a regular file, opened without blocking: a FIFO blocked the open forever,
//     and /dev/zero or /dev/urandom (named directly, by a link or by an absolute URI) kept
//     OpenImageIO's format probing reading forever;
//   - an OpenEXR header's attributes must fit in the file (exr_header.h);
//   - the header must declare pixels (a TGA of 4 x 0 made OpenImageIO divide by zero) and at most
//     kMaxDecodedImageBytes of them decoded, whatever the layout: a texture is read whole into
//     its MIP map (image/mip_map.h), and OpenImageIO's readers hold an untiled image whole (a
//     27 KB tiled TIFF declaring 32768 x 32768 took 6.9 GB); and so may one tile.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rt {

// The most bytes an image may decode to: width x height x channels x the bytes of its pixel type,
// by its data window or its display window, whichever is larger (OpenImageIO makes an untiled
// image's MIP levels at the display window's size).
constexpr std::uint64_t kMaxDecodedImageBytes = std::uint64_t(1) << 30;

// What an image's header declares about the memory it takes.
struct ImageHeader {
    int width = 0, height = 0;  // its finest level's pixels
    int channels = 0;
    int channelBytes = 0;            // the bytes of a channel's value as stored (1 for 8 bits)
    bool floatingPoint = false;      // half, float or double values
    std::uint64_t decodedBytes = 0;  // its finest level, decoded (see kMaxDecodedImageBytes)
};

// The outcome of the check: one of the three is set.
struct ImageHeaderCheck {
    std::optional<std::string> refusal{};     // why it must not be read at all: an input error
    std::optional<std::string> unreadable{};  // why OpenImageIO cannot read it (a missing file too)
    ImageHeader header{};                     // otherwise
};

// Why OpenImageIO must not open the file at `path` at all: "is a FIFO, not a regular file" (told
// without blocking), or an OpenEXR attribute beyond the file; nullopt otherwise, also when it
// cannot be opened (OpenImageIO then says why). The first part of checkImageHeader, for any
// image rt reads (an output rt-render --skip-existing looks at, too).
std::optional<std::string> imageFileRefusal(const std::string& path);

// Checks the image file at `path`: "is a FIFO, not a regular file", "is 32768 x 32768 pixels of
// 3 channels, 3.0 GiB decoded, more than the 1 GiB an image may take", ...
ImageHeaderCheck checkImageHeader(const std::string& path);

// The same for a picture embedded in a model, `name` its file name (whose extension picks the reader).
ImageHeaderCheck checkImageHeader(const std::vector<std::uint8_t>& bytes, const std::string& name);

}  // namespace rt
