// Small text helpers shared by the layers: ASCII lower case, for the case-insensitive names
// of formats, extensions and file names; the numbers of option values such as "X,Y,Z"; sizes for messages.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

// `text` with A-Z turned to a-z; other bytes (UTF-8 included) are left alone.
std::string lowerCase(std::string text);

// The extension of a path in lower case, with its dot (".gltf"); empty if there is none.
std::string lowerCaseExtension(const std::string& path);

// `text` as exactly N numbers of type T, each followed by `separator` but the last: the one
// grammar of option values such as "1,2.5,3" (X,Y,Z), "4x4" (CxR), "0..7" (A..B), "3/16" (I/N).
// Nothing if it is anything else: a missing, empty or extra field, a space or '+', a number T
// cannot hold. (from_chars: no locale, and the whole field must be the number.)
template <class T, std::size_t N>
std::optional<std::array<T, N>> parseSeparated(std::string_view text, std::string_view separator) {
    std::array<T, N> values{};
    for (std::size_t i = 0; i < N; ++i) {
        const std::size_t end = i + 1 < N ? text.find(separator) : text.size();
        if (end == std::string_view::npos) return std::nullopt;
        const char* last = text.data() + end;
        const auto [stop, error] = std::from_chars(text.data(), last, values[i]);
        if (end == 0 || error != std::errc() || stop != last) return std::nullopt;
        text.remove_prefix(std::min(text.size(), end + separator.size()));
    }
    return values;
}

// The fewest single-character insertions, deletions and substitutions that turn `a` into `b`
// (Levenshtein's distance), for "did you mean" in messages about mistyped names.
std::size_t editDistance(std::string_view a, std::string_view b);

// The name of `names` nearest to `typed` by editDistance, if it is near enough to be what was
// meant (at most a third of its length changed, and at most 3 characters: a one-letter option is no typo
// of another), else nothing.
std::optional<std::string> nearestName(std::string_view typed, const std::vector<std::string>& names);

// "6.4 GB" (decimal gigabytes, one decimal), for messages about memory.
std::string gigabytes(std::uint64_t bytes);

}  // namespace rt
