// Rays per second for an 800x600 render of the bundled demo scene (scenes/demo.xml) with
// shadows and reflection depth 3, the thesis's measuring setup (4.3), on 1 and 2 threads.
// The scene is the source tree's (or given by $RT_BENCH_SCENE); the accelerator is
// the KD tree unless $RT_BENCH_ACCEL says naive or bsp. Wall-clock time.
//   build/release/bench/bench_render --benchmark_min_time=1
#include <benchmark/benchmark.h>

#include <cstdlib>

#include "accel/build.h"
#include "import/load_scene.h"
#include "render/renderer.h"

namespace {

struct Prepared {
    rt::Scene scene;
    std::unique_ptr<rt::Accelerator> accel;
};

const Prepared& demo() {
    static const Prepared prepared = [] {
        const char* env = std::getenv("RT_BENCH_SCENE");
        const std::string path = env ? env : RT_SOURCE_DIR "/scenes/demo.xml";
        Prepared p{rt::loadScene(path), nullptr};  // as rt-render reads it
        const char* accel = std::getenv("RT_BENCH_ACCEL");
        rt::AccelSettings settings;
        settings.kind = rt::parseAccelKind(accel ? accel : "kd").value_or(rt::AccelKind::Kd);
        p.accel = rt::buildAccelerator(p.scene.primitives, settings);
        return p;
    }();
    return prepared;
}

void BM_RenderDemo800x600(benchmark::State& state) {
    const Prepared& p = demo();
    rt::RenderSettings settings;
    settings.width = 800;
    settings.height = 600;
    settings.shadows = true;
    settings.reflectionDepth = 3;
    settings.threads = int(state.range(0));
    std::uint64_t rays = 0;
    for (auto _ : state) {
        rt::RenderStats stats;
        const rt::Framebuffer image = rt::render(p.scene, *p.accel, settings, stats);
        benchmark::DoNotOptimize(image.pixels().data());
        rays += stats.counters.rays();
    }
    state.counters["rays_per_second"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    state.counters["rays_per_frame"] = double(rays) / double(state.iterations());
    state.SetLabel(p.accel->stats().name);
}
BENCHMARK(BM_RenderDemo800x600)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
