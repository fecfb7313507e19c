// An 8-bit sRGB picture for display (the heat map): already display-referred, so it is
// written to PNG as it is, without a colour transform.
#pragma once

#include <cstdint>
#include <vector>

namespace rt {

struct Rgb8 {
    std::uint8_t r = 0, g = 0, b = 0;
    bool operator==(const Rgb8&) const = default;
};

class RgbImage {
public:
    RgbImage(int width, int height, Rgb8 fill = {});

    int width() const { return width_; }
    int height() const { return height_; }
    Rgb8 at(int x, int y) const;
    // Pixels outside the image are ignored, so drawing code need not clip.
    void set(int x, int y, Rgb8 c);
    void fillRect(int x0, int y0, int w, int h, Rgb8 c);

    // Row-major, row 0 at the top, three bytes per pixel.
    const std::vector<std::uint8_t>& bytes() const { return pixels_; }

private:
    int width_, height_;
    std::vector<std::uint8_t> pixels_;
};

}  // namespace rt
