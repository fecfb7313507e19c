#include "render/renderer.h"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include "core/stopwatch.h"
#include "render/adaptive.h"
#include "render/film/noise_threshold.h"
#include "render/film/pixel_estimate.h"
#include "render/integrators/path_tracer.h"
#include "render/integrators/tracer.h"

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

// The items in the order the threads take them: a golden-ratio stride through the picture,
// so that every stretch of the render samples the whole frame (sky and detail alike) and the
// work done so far predicts the time left. Pixels are independent, so the order changes no bit.
template <class Item>
std::vector<Item> spreadOut(const std::vector<Item>& items) {
    const std::size_t n = items.size();
    std::size_t stride = std::max<std::size_t>(1, std::size_t(double(n) * 0.6180339887));
    while (std::gcd(stride, n) > 1) ++stride;  // coprime: the walk visits every item once
    std::vector<Item> order;
    order.reserve(n);
    for (std::size_t i = 0, k = 0; i < n; ++i, k = (k + stride) % n) order.push_back(items[k]);
    return order;
}

int threadCount(const RenderSettings& settings) {
    return settings.threads > 0 ? settings.threads : omp_get_max_threads();
}

// What every pass over the picture shares: the blocks in their order, the threads with their
// counters, the progress, the clock of --time-limit and the stop flag of a window.
class BlockLoop {
public:
    BlockLoop(const RenderSettings& settings, std::vector<PixelWindow> blocks, const RenderProgress& progress,
              const RenderWatch& watch)
        : settings_(settings),
          blocks_(spreadOut(blocks)),
          progress_(progress),
          watch_(watch),
          threads_(threadCount(settings)),
          perThread_(std::size_t(threads_)) {
        const PixelWindow w = settings.window();
        samplesTotal_ = std::uint64_t(w.width()) * std::uint64_t(w.height()) * std::uint64_t(settings.pixelSamples);
    }

    int threads() const { return threads_; }
    RenderCounters& counters() { return perThread_[std::size_t(omp_get_thread_num())].counters; }

    // True once the time limit has passed or the watcher asked to stop: no further work starts.
    bool halted() {
        if (settings_.timeLimitSeconds > 0 && !timeUp_.load(std::memory_order_relaxed) &&
            stopwatch_.seconds() >= settings_.timeLimitSeconds)
            timeUp_.store(true, std::memory_order_relaxed);
        return timeUp_.load(std::memory_order_relaxed) || (watch_.stop && watch_.stop->load(std::memory_order_relaxed));
    }
    bool timeUp() const { return timeUp_.load(std::memory_order_relaxed); }

    // Runs traceBlock(block, counters) on every block over the threads. A finished block counts
    // samplesPerPixel camera samples a pixel towards the progress and, given `image`, goes to
    // the watcher. False when the render halted before every block was finished.
    template <class TraceBlock>
    bool run(const TraceBlock& traceBlock, int samplesPerPixel, const Framebuffer* image) {
        const int total = int(blocks_.size());
#pragma omp parallel for num_threads(threads_) schedule(dynamic)
        for (int i = 0; i < total; ++i) {
            const PixelWindow& b = blocks_[std::size_t(i)];
            if (halted() || !traceBlock(b, counters())) continue;
            if (!progress_ && !(image && watch_.blockDone)) continue;
#pragma omp critical(rt_render_progress)
            {
                samplesDone_ += std::uint64_t(b.width()) * std::uint64_t(b.height()) * std::uint64_t(samplesPerPixel);
                if (progress_) progress_(samplesDone_, samplesTotal_);
                if (image && watch_.blockDone) watch_.blockDone(*image, b);
            }
        }
        return !halted();
    }

    // Calls traceRun(x0, y, count) on runs of up to `length` pixels of `block`, row by row, left
    // to right; false if the render halted first (checked at every run: one pixel of a million
    // lights can take a tenth of a second).
    template <class TraceRun>
    bool eachRun(const PixelWindow& block, int length, const TraceRun& traceRun) {
        for (int y = block.y0; y < block.y1; ++y)
            for (int x = block.x0; x < block.x1; x += length) {
                if (halted()) return false;
                traceRun(x, y, std::min(length, block.x1 - x));
            }
        return true;
    }
    // Calls tracePixel(x, y) on each pixel of `block`, as eachRun.
    template <class TracePixel>
    bool eachPixel(const PixelWindow& block, const TracePixel& tracePixel) {
        return eachRun(block, 1, [&](int x, int y, int) { tracePixel(x, y); });
    }

    // The render part of `stats`: the time, the summed counters, the objects, lights and threads.
    void finish(const Scene& scene, int samplesPerPixel, RenderStats& stats) const {
        stats.renderSeconds = stopwatch_.seconds();
        stats.counters = {};
        for (const ThreadCounters& t : perThread_) stats.counters += t.counters;
        stats.objects = scene.primitives.size();
        stats.lights = scene.lights.size();
        stats.threads = threads_;
        stats.samplesPerPixel = samplesPerPixel;
        stats.timeLimitReached = timeUp();
    }

private:
    const RenderSettings& settings_;
    std::vector<PixelWindow> blocks_;
    const RenderProgress& progress_;
    const RenderWatch& watch_;
    int threads_;
    std::vector<ThreadCounters> perThread_;
    std::uint64_t samplesDone_ = 0, samplesTotal_ = 0;
    std::atomic<bool> timeUp_{false};
    const Stopwatch stopwatch_;
};

// The Whitted tracer in one pass: every pixel takes all its -S samples at once (their jittered
// grid needs them all), so a render cut short by --time-limit has no whole picture. With one
// sample a pixel, runs of kPacketSize pixels of a row trace their camera rays as one packet
// (Tracer::pixelRun; the same bits). Adaptive
// subsampling needs the tracer's object ids (validate() refuses it with the path tracer).
Framebuffer renderWhitted(const Tracer& tracer, const Scene& scene, const RenderSettings& settings, RenderStats& stats,
                          const RenderProgress& progress, const RenderWatch& watch) {
    Framebuffer image(settings.width, settings.height, settings.window(), scene.background, !settings.aovs.empty());
    std::optional<AdaptiveSampler> adaptive;
    if (settings.adaptiveGrid) adaptive.emplace(tracer, settings);
    const int blockSize = adaptive ? adaptive->blockSize() : kBlockSize;
    BlockLoop loop(settings, blocksOf(settings.window(), blockSize), progress, watch);
    if (adaptive) {
        const auto corners = std::int64_t(adaptive->cornerCount());
#pragma omp parallel for num_threads(loop.threads()) schedule(dynamic, 64)
        for (std::int64_t i = 0; i < corners; ++i)
            if (!loop.halted()) adaptive->traceCorner(std::size_t(i), loop.counters());
    }
    const bool whole = loop.run(
        [&](const PixelWindow& b, RenderCounters& counters) {
            if (adaptive) {
                adaptive->fill(b, image, counters);
                return true;
            }
            if (tracer.tracesPackets())
                return loop.eachRun(b, kPacketSize, [&](int x0, int y, int count) {
                    std::array<Color, kPacketSize> colors;
                    std::array<float, kPacketSize> coverages;
                    tracer.pixelRun(x0, y, count, counters, colors.data(), coverages.data());
                    for (int i = 0; i < count; ++i) {
                        image.at(x0 + i, y) = colors[std::size_t(i)];
                        image.alphaAt(x0 + i, y) = coverages[std::size_t(i)];
                    }
                });
            return loop.eachPixel(b, [&](int x, int y) {
                image.at(x, y) = tracer.pixel(x, y, counters, image.alphaAt(x, y), image.aovsAt(x, y));
            });
        },
        settings.pixelSamples, &image);
    loop.finish(scene, whole ? settings.pixelSamples : 0, stats);
    stats.samplesTaken = whole ? stats.counters.camera.rays : 0;
    return image;
}

// What the path tracer's passes have gathered in each pixel of the window (row by row): its
// estimate and, with --aov, its AOV sums.
struct PassState {
    std::vector<PixelEstimate> estimates;
    std::vector<AovSums> aovs;  // empty without --aov

    PassState(std::size_t pixels, bool withAovs) : estimates(pixels), aovs(withAovs ? pixels : 0) {}
};

// Writes pixel i (at x, y) of `state` into the picture.
void writePixel(const PassState& state, std::size_t i, int x, int y, Framebuffer& image) {
    const PixelEstimate& e = state.estimates[i];
    image.at(x, y) = e.mean();
    image.alphaAt(x, y) = e.coverage();
    if (PixelAovs* aovs = image.aovsAt(x, y)) *aovs = state.aovs[i].mean(e.varianceOfMean());
}

// Writes every pixel of window `w` of `state` into the picture, a row per thread at a time.
void writePicture(const PassState& state, const PixelWindow& w, int threads, Framebuffer& image) {
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int y = w.y0; y < w.y1; ++y) {
        std::size_t i = std::size_t(y - w.y0) * std::size_t(w.width());
        for (int x = w.x0; x < w.x1; ++x, ++i) writePixel(state, i, x, y, image);
    }
}

// The path tracer in passes: pass k takes sample k of every pixel, so the picture after K
// passes holds the same bits as a render with -S K (PixelEstimate and AovSums add in the same
// order), for any thread count or region split. Each pixel's new sample is added where it is
// traced, in the parallel loop, to a copy of the pixel's state (`next`), so that a pass cut
// short by --time-limit or the watcher's stop can be dropped whole: the picture is made from
// `done`, the passes that finished, once at the end and, for a watcher, after every pass (not
// per sample: a pixel's mean, coverage and AOVs cost as much as its bookkeeping). The watcher
// may end the render after a pass (endAfterPass). With --noise-threshold a pixel whose own
// samples say it has converged is skipped (render/film/noise_threshold.h), and the passes end once
// every pixel has.
Framebuffer renderPath(const PathTracer& tracer, const Scene& scene, const RenderSettings& settings, RenderStats& stats,
                       const RenderProgress& progress, const RenderWatch& watch) {
    const PixelWindow w = settings.window();
    const bool withAovs = !settings.aovs.empty();
    const NoiseThreshold noise(settings);
    const bool withVariance = withAovs || noise.enabled();  // the variance AOV or the noise threshold reads it
    Framebuffer image(settings.width, settings.height, w, scene.background, withAovs);
    BlockLoop loop(settings, blocksOf(w, kBlockSize), progress, watch);
    PassState done(image.pixels().size(), withAovs), next = done;
    // the pass's non-finite samples, per thread, kept only if the pass is
    std::vector<NonFiniteSamples> passNonFinite(std::size_t(loop.threads()));
    std::vector<std::uint64_t> stillSampling(std::size_t(loop.threads()));  // pixels not stopped after the pass
    NonFiniteSamples nonFinite;
    int passes = 0;
    for (; passes < settings.pixelSamples; ++passes) {
        std::fill(passNonFinite.begin(), passNonFinite.end(), NonFiniteSamples{});
        std::fill(stillSampling.begin(), stillSampling.end(), 0);
        const bool whole = loop.run(
            [&](const PixelWindow& b, RenderCounters& counters) {
                const std::size_t thread = std::size_t(omp_get_thread_num());
                return loop.eachPixel(b, [&](int x, int y) {
                    const std::size_t i = std::size_t(y - w.y0) * std::size_t(w.width()) + std::size_t(x - w.x0);
                    next.estimates[i] = done.estimates[i];
                    AovSums* aovs = withAovs ? &(next.aovs[i] = done.aovs[i]) : nullptr;
                    if (noise.stopped(done.estimates[i])) return;
                    bool seen = false;
                    const Color c = tracer.sample(x, y, passes, counters, seen, aovs);  // before add() reads `seen`
                    if (!next.estimates[i].add(c, seen, withVariance)) passNonFinite[thread].add(x, y);
                    stillSampling[thread] += !noise.stopped(next.estimates[i]);
                });
            },
            1, nullptr);
        if (!whole) break;  // the pass cut short is dropped: `done` holds the whole ones
        std::swap(done, next);
        for (const NonFiniteSamples& n : passNonFinite) nonFinite += n;
        if (watch.blockDone) {
            writePicture(done, w, loop.threads(), image);
            watch.blockDone(image, w);
        }
        const bool converged = std::accumulate(stillSampling.begin(), stillSampling.end(), std::uint64_t(0)) == 0;
        if (converged || (watch.endAfterPass && passes + 1 < settings.pixelSamples && watch.endAfterPass())) {
            ++passes;  // this one is whole, and the picture holds it
            break;
        }
    }
    writePicture(done, w, loop.threads(), image);
    loop.finish(scene, passes, stats);
    stats.counters.nonFinite += nonFinite;
    stats.samplesTaken = 0;
    for (const PixelEstimate& e : done.estimates) stats.samplesTaken += std::uint64_t(e.samples);
    return image;
}

// About `count` pixels of the window on an even grid, in the golden-stride order, so that a
// probe cut short still sees the whole frame.
std::vector<std::pair<int, int>> probePixels(const PixelWindow& w, int count) {
    const int side = std::max(1, int(std::sqrt(double(count))));
    const int columns = std::min(side, w.width()), rows = std::min(side, w.height());
    std::vector<std::pair<int, int>> pixels;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c)
            pixels.emplace_back(w.x0 + int((c + 0.5) * w.width() / columns), w.y0 + int((r + 0.5) * w.height() / rows));
    return spreadOut(pixels);
}

// `probe` is set up as `settings` but with one sample a pixel and no --adaptive.
template <class Integrator>
RenderEstimate estimateWith(const Integrator& probe, const RenderSettings& settings, int count, double maxSeconds) {
    RenderEstimate e;
    const std::vector<std::pair<int, int>> pixels = probePixels(settings.window(), count);
    // One untimed, uncounted pixel first pays what only the first pays: tables built on first
    // use, cold caches. Without it a path-traced probe predicted 12 times the render's time.
    RenderCounters warmUp;
    float coverage;
    probe.pixel(pixels.front().first, pixels.front().second, warmUp, coverage);
    const Stopwatch stopwatch;
    for (const auto& [x, y] : pixels) {
        if (e.probePixels > 0 && stopwatch.seconds() >= maxSeconds) break;
        probe.pixel(x, y, e.probe, coverage);
        ++e.probePixels;
    }
    e.probeSeconds = stopwatch.seconds();
    const PixelWindow w = settings.window();
    e.cameraSamples = std::uint64_t(w.width()) * std::uint64_t(w.height()) * std::uint64_t(settings.pixelSamples);
    const double perProbe = double(e.cameraSamples) / double(e.probePixels);
    e.rays = double(e.probe.rays()) * perProbe;
    e.intersectionTests = double(e.probe.total().intersectionTests) * perProbe;
    e.threads = threadCount(settings);
    e.seconds = e.probeSeconds * perProbe / e.threads;
    return e;
}

}  // namespace

RenderEstimate estimateRender(const ShadingContext& context, const Accelerator& accel, const RenderSettings& settings,
                              int probePixels, double maxProbeSeconds) {
    validate(settings);
    RenderSettings probe = settings;
    probe.pixelSamples = 1;
    probe.adaptiveGrid = 0;
    probe.aovs.clear();
    if (settings.integrator == Integrator::Path)
        return estimateWith(PathTracer(context, accel, probe), settings, probePixels, maxProbeSeconds);
    return estimateWith(Tracer(context, accel, probe), settings, probePixels, maxProbeSeconds);
}

Framebuffer render(const ShadingContext& context, const Accelerator& accel, const RenderSettings& settings,
                   RenderStats& stats, const RenderProgress& progress, const RenderWatch& watch) {
    const Scene& scene = context.scene;
    validate(settings);
    if (settings.integrator == Integrator::Path)
        return renderPath(PathTracer(context, accel, settings), scene, settings, stats, progress, watch);
    return renderWhitted(Tracer(context, accel, settings), scene, settings, stats, progress, watch);
}

}  // namespace rt
