// Text output (thesis 3.4.4, TextRenderOutput): the picture as grey levels drawn with
// characters, one character per pixel, for a terminal or a text file.
#pragma once

#include <string>
#include <vector>

namespace rt {

// Display-encoded RGB in [0, 1] (packed, width * height * 3 floats), one line per row.
// Each pixel's Rec.709 luma picks a character from a ramp running from dark ' ' to bright '@'.
std::string asciiArt(const std::vector<float>& displayRgb, int width, int height);

}  // namespace rt
