#include "render/adaptive.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "render/renderer.h"

namespace rt {

namespace {

// std::lerp per channel: exact at both ends and where a == b, so a flat cell stays flat to the bit.
Color lerp(const Color& a, const Color& b, float t) {
    return {std::lerp(a.r, b.r, t), std::lerp(a.g, b.g, t), std::lerp(a.b, b.b, t)};
}

// Where pixel p lies between corners a and b (b >= a), from 0 to 1.
float fraction(int p, int a, int b) { return b > a ? float(p - a) / float(b - a) : 0.0f; }

}  // namespace

AdaptiveSampler::AdaptiveSampler(const Tracer& tracer, const RenderSettings& settings)
    : tracer_(tracer),
      width_(settings.width),
      height_(settings.height),
      grid_(settings.adaptiveGrid),
      blockSize_(std::max(grid_, kBlockSize)),
      threshold_(settings.adaptiveThreshold) {
    const PixelWindow w = settings.window();
    kx0_ = w.x0 / grid_;
    ky0_ = w.y0 / grid_;
    kx1_ = (w.x1 - 1) / grid_ + 1;  // the right corner of the last cell the window touches
    ky1_ = (w.y1 - 1) / grid_ + 1;
    lattice_.resize(std::size_t(kx1_ - kx0_ + 1) * std::size_t(ky1_ - ky0_ + 1));
}

void AdaptiveSampler::traceCorner(std::size_t i, RenderCounters& counters) {
    const std::size_t columns = std::size_t(kx1_ - kx0_ + 1);
    const int kx = kx0_ + int(i % columns), ky = ky0_ + int(i / columns);
    lattice_[i] = trace(std::min(kx * grid_, width_ - 1), std::min(ky * grid_, height_ - 1), counters);
}

CornerSample AdaptiveSampler::trace(int x, int y, RenderCounters& counters) const {
    CornerSample s;
    PixelAovs aovs;  // for the object id of the first camera ray
    s.color = tracer_.pixel(x, y, counters, s.alpha, &aovs);
    s.object = aovs.primitive;
    return s;
}

// A coarse corner sits on a multiple of the grid or, where the edge cuts the last cell, on the last row or column.
bool AdaptiveSampler::onLattice(int x, int y) const {
    return (x % grid_ == 0 || x == width_ - 1) && (y % grid_ == 0 || y == height_ - 1);
}

std::size_t AdaptiveSampler::latticeIndex(int x, int y) const {
    const int kx = x % grid_ == 0 ? x / grid_ : kx1_;
    const int ky = y % grid_ == 0 ? y / grid_ : ky1_;
    return std::size_t(ky - ky0_) * std::size_t(kx1_ - kx0_ + 1) + std::size_t(kx - kx0_);
}

bool AdaptiveSampler::agree(const CornerSample& a, const CornerSample& b) const {
    const float difference = std::max({std::abs(a.color.r - b.color.r), std::abs(a.color.g - b.color.g),
                                       std::abs(a.color.b - b.color.b), std::abs(a.alpha - b.alpha)});
    return a.object == b.object && difference < threshold_;
}

// One block's work: its cells, split as their corners ask, and the corners traced for them,
// each once (neighbouring cells share corners).
class AdaptiveSampler::Block {
public:
    Block(const AdaptiveSampler& sampler, const PixelWindow& block, Framebuffer& image, RenderCounters& counters)
        : s_(sampler),
          block_(block),
          image_(image),
          counters_(counters),
          x0_(block.x0 / sampler.blockSize_ * sampler.blockSize_),
          y0_(block.y0 / sampler.blockSize_ * sampler.blockSize_),
          side_(sampler.blockSize_ + 1),
          corners_(std::size_t(side_) * std::size_t(side_)) {}

    void fillAll() {
        const int g = s_.grid_;
        for (int y = block_.y0 / g * g; y < block_.y1; y += g)
            for (int x = block_.x0 / g * g; x < block_.x1; x += g) fill(x, y, g);
    }

private:
    // The cell of `size` pixels at (x, y), both multiples of size, split until its corners agree.
    void fill(int x, int y, int size) {
        const PixelWindow cell{x, y, x + size, y + size};
        if (x >= block_.x1 || y >= block_.y1 || cell.x1 <= block_.x0 || cell.y1 <= block_.y0) return;
        if (size == 1) {
            image_.at(x, y) = corner(x, y).color;
            image_.alphaAt(x, y) = corner(x, y).alpha;
            return;
        }
        const int xr = std::min(cell.x1, s_.width_ - 1), yb = std::min(cell.y1, s_.height_ - 1);
        const CornerSample &a = corner(x, y), &b = corner(xr, y), &c = corner(x, yb), &d = corner(xr, yb);
        if (s_.agree(a, b) && s_.agree(a, c) && s_.agree(b, d) && s_.agree(c, d)) return interpolate(cell, xr, yb);
        const int half = size / 2;
        fill(x, y, half);
        fill(x + half, y, half);
        fill(x, y + half, half);
        fill(x + half, y + half, half);
    }

    // Bilinear between the corners; a pixel that is a corner keeps its traced value.
    void interpolate(const PixelWindow& cell, int xr, int yb) {
        const CornerSample &a = corner(cell.x0, cell.y0), &b = corner(xr, cell.y0), &c = corner(cell.x0, yb),
                           &d = corner(xr, yb);
        for (int y = std::max(cell.y0, block_.y0); y < std::min(cell.y1, block_.y1); ++y) {
            const float ty = fraction(y, cell.y0, yb);
            for (int x = std::max(cell.x0, block_.x0); x < std::min(cell.x1, block_.x1); ++x) {
                const bool isCorner = (x == cell.x0 || x == xr) && (y == cell.y0 || y == yb);
                if (isCorner) {
                    image_.at(x, y) = corner(x, y).color;
                    image_.alphaAt(x, y) = corner(x, y).alpha;
                    continue;
                }
                const float tx = fraction(x, cell.x0, xr);
                image_.at(x, y) = lerp(lerp(a.color, b.color, tx), lerp(c.color, d.color, tx), ty);
                image_.alphaAt(x, y) = std::lerp(std::lerp(a.alpha, b.alpha, tx), std::lerp(c.alpha, d.alpha, tx), ty);
                ++counters_.interpolatedPixels;
            }
        }
    }

    const CornerSample& corner(int x, int y) {
        std::optional<CornerSample>& slot = corners_[std::size_t(y - y0_) * std::size_t(side_) + std::size_t(x - x0_)];
        if (!slot) slot = s_.onLattice(x, y) ? s_.lattice_[s_.latticeIndex(x, y)] : s_.trace(x, y, counters_);
        return *slot;
    }

    const AdaptiveSampler& s_;
    const PixelWindow& block_;
    Framebuffer& image_;
    RenderCounters& counters_;
    int x0_, y0_, side_;  // the aligned square the block lies in, and its corners' row length
    std::vector<std::optional<CornerSample>> corners_;
};

void AdaptiveSampler::fill(const PixelWindow& block, Framebuffer& image, RenderCounters& counters) const {
    Block(*this, block, image, counters).fillAll();
}

}  // namespace rt
