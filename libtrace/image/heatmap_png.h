// Writes rt-inspect's heat map (8-bit sRGB, already display-referred) to a PNG through
// OpenImageIO, atomically. No colour transform is applied: the colours are the colour
// map's sRGB values. (Renders, which are scene-linear, go through OpenColorIO instead.)
#pragma once

#include <string>

#include "inspect/rgb_image.h"

namespace rt {

// Throws std::runtime_error naming the file if it cannot be written.
void writeHeatmapPng(const std::string& path, const RgbImage& image);

}  // namespace rt
