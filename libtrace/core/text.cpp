#include "core/text.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <numeric>

namespace rt {

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

std::string lowerCaseExtension(const std::string& path) {
    return lowerCase(std::filesystem::path(path).extension().string());
}

std::size_t editDistance(std::string_view a, std::string_view b) {
    // Wagner-Fischer, one row at a time: row[j] is the distance from a's first i characters to b's first j.
    std::vector<std::size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), std::size_t(0));
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substituted = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substituted});
        }
    }
    return row[b.size()];
}

std::optional<std::string> nearestName(std::string_view typed, const std::vector<std::string>& names) {
    const std::size_t allowed = std::min<std::size_t>(3, typed.size() / 3);
    std::optional<std::string> nearest;
    std::size_t best = allowed + 1;
    for (const std::string& name : names)
        if (const std::size_t d = editDistance(typed, name); d < best) {
            best = d;
            nearest = name;
        }
    return nearest;
}

std::string gigabytes(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", double(bytes) / 1e9);
    return text;
}

}  // namespace rt
