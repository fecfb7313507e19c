#include "inspect/heatmap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "inspect/bitmap_font.h"
#include "inspect/color_map.h"

namespace rt {

float heatPosition(float value, float maximum, HeatScale scale) {
    if (!(maximum > 0) || !(value > 0)) return 0;
    const float t = scale == HeatScale::Log ? std::log1p(value) / std::log1p(maximum) : value / maximum;
    return std::min(t, 1.0f);
}

std::vector<float> heatTicks(float maximum, HeatScale scale) {
    std::vector<float> ticks{0};
    if (!(maximum > 0) || !std::isfinite(maximum)) return ticks;
    if (scale == HeatScale::Linear) {
        // A step of 1, 2 or 5 times a power of ten giving about five intervals. In double and
        // counted: a float sum stops growing near 3e38 and never starts from a step of 1e-46.
        const double rough = double(maximum) / 5;
        const double decade = std::pow(10.0, std::floor(std::log10(rough)));
        const double step = decade * (rough >= 5 * decade ? 5 : rough >= 2 * decade ? 2 : 1);
        for (int i = 1; i * step <= double(maximum) * 1.0001; ++i) ticks.push_back(float(i * step));
        return ticks;
    }
    // Powers of ten, with 2 and 5 between them when there are few decades.
    const bool fine = maximum < 1000;
    for (float decade = 1; decade <= maximum; decade *= 10) {
        for (const float m : {1.0f, 2.0f, 5.0f}) {
            if (m != 1 && !fine) continue;
            if (m * decade <= maximum) ticks.push_back(m * decade);
        }
    }
    return ticks;
}

float heatMaximum(const std::vector<float>& cost, const HeatmapOptions& options) {
    if (options.maximum) return *options.maximum;
    float m = 1;
    for (const float c : cost) m = std::max(m, c);
    return m;
}

namespace {

constexpr Rgb8 kStripBackground{24, 24, 24};
constexpr Rgb8 kTextColor{235, 235, 235};

std::string tickLabel(float v) {
    char buf[32];
    if (v == std::round(v) && v < 1e7f)
        std::snprintf(buf, sizeof buf, "%.0f", v);
    else
        std::snprintf(buf, sizeof buf, "%.3g", v);
    return buf;
}

// The colour bar, its ticks and labels, and the caption and summary, in the strip below the
// picture. Lettering grows with the picture (2x from 640 pixels wide); the summary moves
// under the caption when both do not fit on one line.
class ColorBarStrip {
public:
    ColorBarStrip(int width, std::string caption, std::string summary)
        : width_(width), s_(std::max(1, width / 320)), caption_(std::move(caption)), summary_(std::move(summary)) {
        const int margin = 8 * s_;
        twoLines_ = textWidth(caption_, s_) + 4 * kGlyphAdvance * s_ + textWidth(summary_, s_) > width - 2 * margin;
    }

    int height() const { return (41 + (twoLines_ ? kGlyphHeight + 5 : 0)) * s_; }

    void draw(RgbImage& image, int top, float maximum, HeatScale scale) const {
        const int barTop = top + 4 * s_, barHeight = 10 * s_;
        const int x0 = 8 * s_, x1 = width_ - 8 * s_;  // the bar spans [x0, x1)
        for (int x = x0; x < x1; ++x) {
            const float t = float(x - x0) / float(std::max(1, x1 - x0 - 1));
            image.fillRect(x, barTop, 1, barHeight, viridis(t));
        }
        const int tickTop = barTop + barHeight, labelTop = tickTop + 5 * s_;
        int labelEnd = -width_;  // right edge of the last label, to keep labels apart
        for (const float v : heatTicks(maximum, scale)) {
            const int x = x0 + int(std::lround(heatPosition(v, maximum, scale) * float(x1 - x0 - 1)));
            image.fillRect(x, tickTop, s_, 3 * s_, kTextColor);
            const std::string label = tickLabel(v);
            const int w = textWidth(label, s_);
            const int lx = std::clamp(x - w / 2, 0, width_ - w);
            if (lx < labelEnd + 3 * kGlyphAdvance * s_ / 2) continue;
            drawText(image, lx, labelTop, label, s_, kTextColor);
            labelEnd = lx + w;
        }
        const int captionTop = labelTop + (kGlyphHeight + 5) * s_;
        drawText(image, x0, captionTop, caption_, s_, kTextColor);
        const int summaryTop = twoLines_ ? captionTop + (kGlyphHeight + 5) * s_ : captionTop;
        drawText(image, twoLines_ ? x0 : x1 - textWidth(summary_, s_), summaryTop, summary_, s_, kTextColor);
    }

private:
    int width_, s_;
    std::string caption_, summary_;
    bool twoLines_;
};

}  // namespace

RgbImage renderHeatmap(const std::vector<float>& cost, int width, int height, const HeatmapOptions& options) {
    if (width <= 0 || height <= 0 || cost.size() != std::size_t(width) * std::size_t(height))
        throw std::invalid_argument("renderHeatmap: the cost buffer does not match the image size");
    const float maximum = heatMaximum(cost, options);
    double sum = 0;
    float largest = 0;
    for (const float c : cost) {
        sum += c;
        largest = std::max(largest, c);
    }
    char summary[96];
    std::snprintf(summary, sizeof summary, "MEAN %.1f  MAX %.0f%s", sum / double(cost.size()), double(largest),
                  options.scale == HeatScale::Log ? "  (LOG SCALE)" : "");
    const ColorBarStrip strip(width, options.caption, summary);

    RgbImage image(width, height + strip.height(), kStripBackground);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.set(x, y,
                      viridis(heatPosition(cost[std::size_t(y) * std::size_t(width) + std::size_t(x)], maximum,
                                           options.scale)));
    strip.draw(image, height, maximum, options.scale);
    return image;
}

}  // namespace rt
