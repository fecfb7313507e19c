// OpenEXR headers walked before OpenImageIO opens a texture (image/image_header.h). OpenEXR 3.1 allocates what an
// attribute's size field declares before it reads the attribute: 760 bytes whose string attribute
// declared 1.85 GB took 1.9 GB of memory in `oiiotool --info` and in rt-render alike
// (fuzz_image_texture, 2026-11-28). Every attribute must fit in the file that holds it.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace rt {

// Reads `count` bytes at `offset` into `out`; false where the source ends first.
using ByteReader = std::function<bool(std::uint64_t offset, std::size_t count, std::uint8_t* out)>;

// Why the OpenEXR header of a source of `size` bytes must not be opened ("byte 22: attribute
// 'comments' declares 1852964949 bytes, more than the 738 left in the file"); nullopt when it may
// be, or when the source is not OpenEXR (its magic number is missing): other formats are left to
// their readers.
std::optional<std::string> exrHeaderProblem(const ByteReader& read, std::uint64_t size);

}  // namespace rt
