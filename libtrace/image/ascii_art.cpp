#include "image/ascii_art.h"

#include <algorithm>
#include <string_view>

#include "core/color.h"

namespace rt {

namespace {
// Characters by how much of their cell they cover.
constexpr std::string_view kRamp = " .:-=+*#%@";
}  // namespace

std::string asciiArt(const std::vector<float>& rgb, int width, int height) {
    std::string text;
    text.reserve(std::size_t(width + 1) * std::size_t(height));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float* p = &rgb[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3];
            const float luma = std::clamp(luminance(Color(p[0], p[1], p[2])), 0.0f, 1.0f);
            const auto level = std::min(std::size_t(luma * float(kRamp.size())), kRamp.size() - 1);
            text += kRamp[level];
        }
        text += '\n';
    }
    return text;
}

}  // namespace rt
