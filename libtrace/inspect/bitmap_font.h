// A built-in 5x7 pixel font (digits, capitals and a little punctuation) for the heat
// map's scale and caption, so that labelling a picture needs no font files. Lower-case
// letters are drawn as capitals; characters without a glyph are drawn as '?'.
#pragma once

#include <string_view>

#include "core/rgb_image.h"

namespace rt {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kGlyphAdvance = kGlyphWidth + 1;

// Draws `text` with its top-left corner at (x, y), each font pixel as a scale x scale block.
void drawText(RgbImage& image, int x, int y, std::string_view text, int scale, Rgb8 color);
int textWidth(std::string_view text, int scale);

}  // namespace rt
