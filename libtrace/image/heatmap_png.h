// Writes a heat map (8-bit sRGB, already display-referred) to a PNG through
// OpenImageIO, atomically. No colour transform is applied: the colours are the colour
// map's sRGB values. (Renders, which are scene-linear, go through OpenColorIO instead.)
#pragma once

#include <string>

#include "core/rgb_image.h"

namespace rt {

// `software` is what the PNG's Software field records ("rt-inspect 0.1.0"): the caller's name.
// Throws std::runtime_error naming the file if it cannot be written.
void writeHeatmapPng(const std::string& path, const RgbImage& image, const std::string& software);

}  // namespace rt
