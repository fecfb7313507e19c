// Small text helpers shared by the layers: ASCII lower case, for the case-insensitive names
// of formats, extensions and file names; sizes for messages.
#pragma once

#include <cstdint>
#include <string>

namespace rt {

// `text` with A-Z turned to a-z; other bytes (UTF-8 included) are left alone.
std::string lowerCase(std::string text);

// The extension of a path in lower case, with its dot (".gltf"); empty if there is none.
std::string lowerCaseExtension(const std::string& path);

// "6.4 GB" (decimal gigabytes, one decimal), for messages about memory.
std::string gigabytes(std::uint64_t bytes);

}  // namespace rt
