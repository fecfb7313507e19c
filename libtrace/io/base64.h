// Base64 (RFC 4648, standard alphabet, '=' padding) for model data written inline in a
// scene file, so that a whole scene fits in one stream (rt-convert writing to stdout).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

// Encodes `bytes`, breaking the text into lines of `lineLength` characters (0: one line).
std::string encodeBase64(std::span<const std::uint8_t> bytes, std::size_t lineLength = 0);

// Decodes base64 text, skipping whitespace. On a malformed text returns nothing and sets
// `errorAt` to the offset of the first bad character in `text`.
std::optional<std::vector<std::uint8_t>> decodeBase64(std::string_view text, std::size_t& errorAt);

}  // namespace rt
