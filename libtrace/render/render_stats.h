// Rendering statistics of thesis appendix B and a little more.
#pragma once

#include <cstdint>
#include <utility>

#include "accel/accelerator.h"

namespace rt {

// Camera samples whose colour came out NaN or infinite. Each is replaced by black (0, 0, 0),
// so that no non-finite value reaches an image, and counted here so that it is never replaced
// silently. The first such pixel in scan order (row by row) is kept for the warning: it is the
// same for any thread count and block order.
struct NonFiniteSamples {
    std::uint64_t count = 0;
    int firstX = 0, firstY = 0;  // meaningful when count > 0

    void add(int x, int y) { *this += {1, x, y}; }
    NonFiniteSamples& operator+=(const NonFiniteSamples& o) {
        if (o.count > 0 && (count == 0 || std::pair(o.firstY, o.firstX) < std::pair(firstY, firstX))) {
            firstX = o.firstX;
            firstY = o.firstY;
        }
        count += o.count;
        return *this;
    }
};

// The rays the renderer shot, by kind, each with the accelerator's work for it (traversal
// steps, ray-primitive tests), and the samples that had to be replaced: what rt-render's
// statistics and rt-inspect --rays report.
// Each thread counts in its own copy; the copies are summed at the end.
struct RenderCounters {
    RayCounters camera;      // the thesis's primary rays, -S per pixel
    RayCounters shadow;      // towards each light in front of a hit (a bundle for a soft shadow)
    RayCounters reflection;  // mirror and glossy rays, at any depth
    NonFiniteSamples nonFinite;
    std::uint64_t interpolatedPixels = 0;  // --adaptive: pixels filled in without a camera ray of their own

    RayCounters total() const {
        RayCounters t = camera;
        t += shadow;
        t += reflection;
        return t;
    }
    std::uint64_t rays() const { return camera.rays + shadow.rays + reflection.rays; }
    RenderCounters& operator+=(const RenderCounters& o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        nonFinite += o.nonFinite;
        interpolatedPixels += o.interpolatedPixels;
        return *this;
    }
};

struct RenderStats {
    double preprocessSeconds = 0;  // building the accelerator (the thesis's "preprocessing")
    double renderSeconds = 0;      // wall clock of the parallel render
    std::uint64_t objects = 0;     // primitives after flattening
    std::uint64_t lights = 0;
    std::uint64_t treeNodes = 0;
    int threads = 0;
    RenderCounters counters;
    // The samples every pixel of the picture received: -S, or with --time-limit the whole passes
    // the path tracer finished (with --noise-threshold: the most any pixel received) (0: not one, or a Whitted render
    // cut short; the picture is not whole).
    int samplesPerPixel = 0;
    // The camera samples the picture holds, over all its pixels: the window's pixels times
    // samplesPerPixel, or fewer where --noise-threshold stopped pixels early.
    std::uint64_t samplesTaken = 0;
    bool timeLimitReached = false;  // --time-limit stopped the render before all -S samples

    double testsPerRay() const {
        const RayCounters all = counters.total();
        return all.rays ? double(all.intersectionTests) / double(all.rays) : 0.0;
    }
    double raysPerSecond() const { return renderSeconds > 0 ? double(counters.rays()) / renderSeconds : 0.0; }
};

}  // namespace rt
