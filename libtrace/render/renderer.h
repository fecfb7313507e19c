// Renders a whole image, or a window of it, in 32x32 blocks spread over all cores by
// OpenMP's dynamic schedule (thesis 3.3.4 and 3.5): blocks keep neighbouring rays on
// the same data, and dynamic scheduling gives a free thread the next unfinished block.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "accel/accelerator.h"
#include "render/framebuffer.h"
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
};

// Renders settings.window() of the scene. Fills the render part of `stats` (render time,
// rays, tests, non-finite samples written as black, objects, lights, threads); preprocessing
// time and tree nodes are the caller's.
// Image textures are looked up through `images` (none: they are white).
// Throws rt::InputError for bad settings or a degenerate camera.
Framebuffer render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings, RenderStats& stats,
                   const RenderProgress& progress = {}, const ImageTextures* images = nullptr,
                   const RenderWatch& watch = {});

}  // namespace rt
