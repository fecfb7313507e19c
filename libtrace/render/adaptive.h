// Adaptive subsampling (thesis 2.3, after its reference [6], "Adaptive sub-sample"): rays go
// not through every pixel but through the corners of a grid of G x G pixel cells (G = 8 by
// default). Where the four corners of a cell agree, the cell is filled by bilinear
// interpolation; otherwise it splits into four cells of G/2 and so on down to single pixels,
// which are traced. Corners agree when each neighbouring pair differs by less than the
// threshold in every linear colour channel and in alpha, and their first camera rays hit the
// same object (primitive), so that a small object of the background's colour still splits
// its cells. An object that lies wholly between the corners is missed: that is the method's
// price, and a finer grid lowers it.
//
// The grid is anchored to the image's pixel (0, 0), not to a region, and a traced pixel is
// exactly what a full render traces there (Tracer::pixel, with -S and -D), so every cell decides
// the same whatever region, tile, block or thread renders it: regions merge bit-exactly.
// The image's last row and column close the cells that the edge cuts.
#pragma once

#include <cstdint>
#include <vector>

#include "render/film/framebuffer.h"
#include "render/integrators/tracer.h"
#include "render/render_settings.h"

namespace rt {

// A traced pixel as the cells compare it.
struct CornerSample {
    Color color;
    float alpha = 0;
    std::uint32_t object = kNoId;  // the primitive its first camera ray hit
};

class AdaptiveSampler {
public:
    // settings.adaptiveGrid must be a power of two (validate() checks it); the tracer must outlive the sampler.
    AdaptiveSampler(const Tracer& tracer, const RenderSettings& settings);

    // The renderer's blocks: squares of this side aligned to multiples of it, so a block holds whole cells.
    int blockSize() const { return blockSize_; }

    // The corners of the coarsest cells over the window, traced before the blocks so that
    // neighbouring blocks share them: traceCorner(i) for every i below cornerCount(), in any
    // order and on any thread.
    std::size_t cornerCount() const { return lattice_.size(); }
    void traceCorner(std::size_t i, RenderCounters& counters);

    // Fills `block` (the part inside the window of one aligned square of blockSize()) of `image`.
    void fill(const PixelWindow& block, Framebuffer& image, RenderCounters& counters) const;

private:
    class Block;  // one block's corners, traced once each

    CornerSample trace(int x, int y, RenderCounters& counters) const;
    bool onLattice(int x, int y) const;
    std::size_t latticeIndex(int x, int y) const;
    bool agree(const CornerSample& a, const CornerSample& b) const;

    const Tracer& tracer_;
    int width_, height_, grid_, blockSize_;
    float threshold_;
    int kx0_, ky0_, kx1_, ky1_;  // the lattice's corners k * grid_, the last clamped to the image
    std::vector<CornerSample> lattice_;
};

}  // namespace rt
