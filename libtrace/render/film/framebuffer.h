// The rendered picture: linear, scene-referred float RGB (thesis 3.4.4's outputs
// convert it only when they write), and each pixel's coverage: the fraction of its camera
// rays that hit something (alpha). The colour includes the background the other rays saw,
// so that a picture without alpha needs nothing else; premultiplied() takes it out. A render may cover only a window of
// the full image (render farms, --region); the framebuffer then holds just that window, as an EXR data window sits
// inside its display window.
#pragma once

#include <vector>

#include "core/color.h"
#include "render/film/aov.h"

namespace rt {

// Pixels [x0, x1) x [y0, y1) of an image: the end coordinates are exclusive, as in
// OpenImageIO's ROI, so neighbouring tiles share their edge value (0,0,32,24 and 32,0,64,24).
struct PixelWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool inside(int w, int h) const { return x0 >= 0 && y0 >= 0 && x1 <= w && y1 <= h && !empty(); }
    bool operator==(const PixelWindow&) const = default;
};

class Framebuffer {
public:
    // With `aovs`, each pixel also has its PixelAovs (render/film/aov.h).
    Framebuffer(int fullWidth, int fullHeight, const PixelWindow& window, const Color& background = {},
                bool aovs = false)
        : fullWidth_(fullWidth),
          fullHeight_(fullHeight),
          window_(window),
          background_(background),
          pixels_(std::size_t(window.width()) * std::size_t(window.height())),
          alpha_(pixels_.size(), 1.0f),
          aovs_(aovs ? pixels_.size() : 0) {}

    int fullWidth() const { return fullWidth_; }
    int fullHeight() const { return fullHeight_; }
    const PixelWindow& window() const { return window_; }
    bool isFullImage() const { return window_ == PixelWindow{0, 0, fullWidth_, fullHeight_}; }

    // Pixel (x, y) in full-image coordinates; it must lie inside the window.
    Color& at(int x, int y) { return pixels_[index(x, y)]; }
    const Color& at(int x, int y) const { return pixels_[index(x, y)]; }
    float& alphaAt(int x, int y) { return alpha_[index(x, y)]; }
    float alphaAt(int x, int y) const { return alpha_[index(x, y)]; }
    // The window's pixels, row by row from its top-left corner, and their alpha.
    const std::vector<Color>& pixels() const { return pixels_; }
    const std::vector<float>& alphas() const { return alpha_; }
    const Color& background() const { return background_; }
    bool hasAovs() const { return !aovs_.empty(); }
    PixelAovs* aovsAt(int x, int y) { return hasAovs() ? &aovs_[index(x, y)] : nullptr; }
    const std::vector<PixelAovs>& aovs() const { return aovs_; }

    // Pixel i of pixels() without the background, as over a transparent one: the colour
    // premultiplied by alpha that EXR stores. Exactly 0 where alpha is 0.
    Color premultiplied(std::size_t i) const {
        const float a = alpha_[i];
        if (a == 1) return pixels_[i];
        return a == 0 ? Color{} : pixels_[i] + background_ * (a - 1);
    }

private:
    std::size_t index(int x, int y) const {
        return std::size_t(y - window_.y0) * std::size_t(window_.width()) + std::size_t(x - window_.x0);
    }
    int fullWidth_, fullHeight_;
    PixelWindow window_;
    Color background_;
    std::vector<Color> pixels_;
    std::vector<float> alpha_;
    std::vector<PixelAovs> aovs_;
};

}  // namespace rt
