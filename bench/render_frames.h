// The frame the render benchmarks time, as the thesis measured (4.3): 800x600, shadows,
// reflections to depth 3, on state.range(0) threads, again and again. Shared by
// bench_render (a scene file) and bench_thesis_frame (a thesis scene made in memory), so that
// both time the same work.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdlib>
#include <memory>

#include "accel/build.h"
#include "render/renderer.h"

namespace rt::bench {

struct Prepared {
    Scene scene;
    std::unique_ptr<Accelerator> accel;
};

// The scene with its tree: the KD tree unless $RT_BENCH_ACCEL says naive or bsp.
inline Prepared prepare(Scene scene) {
    const char* accel = std::getenv("RT_BENCH_ACCEL");
    AccelSettings settings;
    settings.kind = parseAccelKind(accel ? accel : "kd").value_or(AccelKind::Kd);
    Prepared p{std::move(scene), nullptr};
    p.accel = buildAccelerator(p.scene.primitives, settings);
    return p;
}

// Renders p's frame once per iteration; reports rays per second and per frame, labelled by the tree.
inline void renderFrames(benchmark::State& state, const Prepared& p) {
    RenderSettings settings;
    settings.width = 800;
    settings.height = 600;
    settings.shadows = true;
    settings.reflectionDepth = 3;
    settings.threads = int(state.range(0));
    std::uint64_t rays = 0;
    for (auto _ : state) {
        RenderStats stats;
        const Framebuffer image = render(p.scene, *p.accel, settings, stats);
        benchmark::DoNotOptimize(image.pixels().data());
        rays += stats.counters.rays();
    }
    state.counters["rays_per_second"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    state.counters["rays_per_frame"] = double(rays) / double(state.iterations());
    state.SetLabel(p.accel->stats().name);
}

}  // namespace rt::bench
