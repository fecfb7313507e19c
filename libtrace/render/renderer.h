// Renders a whole image, or a window of it, in 32x32 blocks spread over all cores by
// OpenMP's dynamic schedule (thesis 3.3.4 and 3.5): blocks keep neighbouring rays on
// the same data, and dynamic scheduling gives a free thread the next unfinished block.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "accel/accelerator.h"
#include "render/film/framebuffer.h"
#include "render/render_settings.h"
#include "render/render_stats.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

constexpr int kBlockSize = 32;  // the thesis found 32x32 best; larger blocks gained nothing

// Called after each finished block with the camera samples traced so far and the total (the
// thesis's ProgressUpdater, counting work rather than blocks: edge blocks are smaller).
// Calls never overlap, so the callback need not be thread-safe.
using RenderProgress = std::function<void(std::uint64_t samplesDone, std::uint64_t samplesTotal)>;

// A render seen from another thread (rt-render -o sdl): each block as it is finished, and a
// flag that stops the render.
struct RenderWatch {
    // Called after each finished block, as the progress is (never two calls at once); the
    // image's pixels inside `block` are final. It should only copy them: the threads wait.
    std::function<void(const Framebuffer& image, const PixelWindow& block)> blockDone;
    // Once it is true the threads start no further block, and render() returns the picture as far as it got.
    const std::atomic<bool>* stop = nullptr;
    // Asked after each whole pass of the path tracer: true ends the render there, keeping every
    // finished pass (rt-render's SIGUSR1 and --on-interrupt write). The Whitted tracer, whose one
    // pass is the whole picture, does not ask.
    std::function<bool()> endAfterPass;
};

// Renders settings.window() of the scene. Fills the render part of `stats` (render time,
// rays, tests, non-finite samples written as black, objects, lights, threads, samples per pixel);
// preprocessing time and tree nodes are the caller's.
//
// The path tracer renders in passes, one sample of every pixel each, so that its picture is
// whole after every pass; with -S K and K passes finished it holds the same bits as in one go.
// settings.timeLimitSeconds stops it at the last whole pass, watch.endAfterPass after the pass
// under way (stats.samplesPerPixel says how many). The Whitted tracer takes all -S samples of a pixel at once: a render
// it cuts short has stats.samplesPerPixel 0, and the picture must not be used. Image textures are looked up through
// the context's lookups (none: they are white). Throws rt::InputError for bad settings or a degenerate camera.
Framebuffer render(const ShadingContext& context, const Accelerator& accel, const RenderSettings& settings,
                   RenderStats& stats, const RenderProgress& progress = {}, const RenderWatch& watch = {});

// What a render will cost, predicted before it starts (rt-render -p): a fixed, even spread of
// the window's pixels (a grid of about `probePixels`, taken in a fixed order) is traced with one
// sample each on one thread (after one untimed pixel that pays the one-time costs), until all
// are done or `maxProbeSeconds` has passed (after at least one pixel), and extrapolated to every
// pixel and sample. The counts depend only on the pixels
// probed; the seconds assume the render's threads share the work evenly. --adaptive and
// --noise-threshold are not taken into account (they trace fewer samples than predicted).
struct RenderEstimate {
    std::uint64_t probePixels = 0;  // traced by the probe
    double probeSeconds = 0;
    RenderCounters probe;             // the probed pixels' rays and the accelerator's work for them
    std::uint64_t cameraSamples = 0;  // of the whole render: pixels x -S
    double rays = 0;                  // predicted for the whole render, of every kind
    double intersectionTests = 0;
    double seconds = 0;  // predicted wall-clock time of the render on `threads` threads
    int threads = 0;
};
RenderEstimate estimateRender(const ShadingContext& context, const Accelerator& accel, const RenderSettings& settings,
                              int probePixels = 256, double maxProbeSeconds = 0.5);

}  // namespace rt
