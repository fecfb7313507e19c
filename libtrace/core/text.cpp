#include "core/text.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace rt {

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

std::string lowerCaseExtension(const std::string& path) {
    return lowerCase(std::filesystem::path(path).extension().string());
}

}  // namespace rt
