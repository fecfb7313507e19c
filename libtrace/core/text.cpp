#include "core/text.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>

namespace rt {

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

std::string lowerCaseExtension(const std::string& path) {
    return lowerCase(std::filesystem::path(path).extension().string());
}

std::string gigabytes(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", double(bytes) / 1e9);
    return text;
}

}  // namespace rt
