#include "render/renderer.h"

#include <omp.h>

#include <algorithm>
#include <numeric>
#include <optional>
#include <type_traits>
#include <vector>

#include "core/stopwatch.h"
#include "render/adaptive.h"
#include "render/path_tracer.h"
#include "render/tracer.h"

namespace rt {

namespace {

// One thread's counters on a cache line of its own, so that counting shares nothing.
struct alignas(64) ThreadCounters {
    RenderCounters counters;
};

// The window cut by a grid of size x size squares anchored to the image's pixel (0, 0).
std::vector<PixelWindow> blocksOf(const PixelWindow& w, int size) {
    std::vector<PixelWindow> blocks;
    for (int y = w.y0 / size * size; y < w.y1; y += size)
        for (int x = w.x0 / size * size; x < w.x1; x += size)
            blocks.push_back(
                {std::max(x, w.x0), std::max(y, w.y0), std::min(x + size, w.x1), std::min(y + size, w.y1)});
    return blocks;
}

// The blocks in the order the threads take them: a golden-ratio stride through the picture,
// so that every stretch of the render samples the whole frame (sky and detail alike) and the
// work done so far predicts the time left. Pixels are independent, so the order changes no bit.
std::vector<PixelWindow> spreadOut(const std::vector<PixelWindow>& blocks) {
    const std::size_t n = blocks.size();
    std::size_t stride = std::max<std::size_t>(1, std::size_t(double(n) * 0.6180339887));
    while (std::gcd(stride, n) > 1) ++stride;  // coprime: the walk visits every block once
    std::vector<PixelWindow> order;
    order.reserve(n);
    for (std::size_t i = 0, k = 0; i < n; ++i, k = (k + stride) % n) order.push_back(blocks[k]);
    return order;
}

// The block loop, for either integrator: both give pixel(x, y, counters, alpha, aovs). Adaptive
// subsampling needs the Whitted tracer's object ids (validate() refuses it with the path tracer).
template <class Integrator>
Framebuffer renderWith(const Integrator& integrator, const Scene& scene, const RenderSettings& settings,
                       RenderStats& stats, const RenderProgress& progress, const RenderWatch& watch) {
    Framebuffer image(settings.width, settings.height, settings.window(), scene.background, settings.aovs);
    std::optional<AdaptiveSampler> adaptive;
    if constexpr (std::is_same_v<Integrator, Tracer>)
        if (settings.adaptiveGrid) adaptive.emplace(integrator, settings);
    const int blockSize = adaptive ? adaptive->blockSize() : kBlockSize;
    const std::vector<PixelWindow> blocks = spreadOut(blocksOf(settings.window(), blockSize));
    const int total = int(blocks.size());
    const int threads = settings.threads > 0 ? settings.threads : omp_get_max_threads();
    std::vector<ThreadCounters> perThread(static_cast<std::size_t>(threads));
    const auto countersOfThisThread = [&perThread]() -> RenderCounters& {
        return perThread[std::size_t(omp_get_thread_num())].counters;
    };
    const auto samplesIn = [&settings](const PixelWindow& w) {
        return std::uint64_t(w.width()) * std::uint64_t(w.height()) * std::uint64_t(settings.pixelSamples);
    };
    const std::uint64_t samplesTotal = samplesIn(settings.window());
    std::uint64_t samplesDone = 0;

    const Stopwatch stopwatch;
    if (adaptive) {
        const auto corners = std::int64_t(adaptive->cornerCount());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
        for (std::int64_t i = 0; i < corners; ++i) adaptive->traceCorner(std::size_t(i), countersOfThisThread());
    }
#pragma omp parallel for num_threads(threads) schedule(dynamic)
    for (int i = 0; i < total; ++i) {
        if (watch.stop && watch.stop->load(std::memory_order_relaxed)) continue;
        const PixelWindow& b = blocks[std::size_t(i)];
        RenderCounters& counters = countersOfThisThread();
        if (adaptive)
            adaptive->fill(b, image, counters);
        else
            for (int y = b.y0; y < b.y1; ++y)
                for (int x = b.x0; x < b.x1; ++x)
                    image.at(x, y) = integrator.pixel(x, y, counters, image.alphaAt(x, y), image.aovsAt(x, y));
        if (progress || watch.blockDone) {
#pragma omp critical(rt_render_progress)
            {
                samplesDone += samplesIn(b);
                if (progress) progress(samplesDone, samplesTotal);
                if (watch.blockDone) watch.blockDone(image, b);
            }
        }
    }
    stats.renderSeconds = stopwatch.seconds();

    stats.counters = {};
    for (const ThreadCounters& t : perThread) stats.counters += t.counters;
    stats.objects = scene.primitives.size();
    stats.lights = scene.lights.size();
    stats.threads = threads;
    return image;
}

}  // namespace

Framebuffer render(const Scene& scene, const Accelerator& accel, const RenderSettings& settings, RenderStats& stats,
                   const RenderProgress& progress, const ImageTextures* images, const RenderWatch& watch) {
    validate(settings);
    if (settings.integrator == Integrator::Path)
        return renderWith(PathTracer(scene, accel, settings, images), scene, settings, stats, progress, watch);
    return renderWith(Tracer(scene, accel, settings, images), scene, settings, stats, progress, watch);
}

}  // namespace rt
