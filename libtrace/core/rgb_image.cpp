#include "core/rgb_image.h"

#include <stdexcept>

namespace rt {

RgbImage::RgbImage(int width, int height, Rgb8 fill) : width_(width), height_(height) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("RgbImage: width and height must be positive");
    pixels_.resize(std::size_t(width) * std::size_t(height) * 3);
    for (std::size_t i = 0; i < pixels_.size(); i += 3) {
        pixels_[i] = fill.r;
        pixels_[i + 1] = fill.g;
        pixels_[i + 2] = fill.b;
    }
}

Rgb8 RgbImage::at(int x, int y) const {
    const std::size_t i = (std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3;
    return {pixels_.at(i), pixels_.at(i + 1), pixels_.at(i + 2)};
}

void RgbImage::set(int x, int y, Rgb8 c) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
    const std::size_t i = (std::size_t(y) * std::size_t(width_) + std::size_t(x)) * 3;
    pixels_[i] = c.r;
    pixels_[i + 1] = c.g;
    pixels_[i + 2] = c.b;
}

void RgbImage::fillRect(int x0, int y0, int w, int h, Rgb8 c) {
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) set(x, y, c);
}

}  // namespace rt
