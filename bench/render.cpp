// Rays per second for an 800x600 render of the bundled demo scene (scenes/demo.xml) with
// shadows and reflection depth 3, the thesis's measuring setup (4.3), on 1 and 2 threads.
// The scene is the source tree's (or given by $RT_BENCH_SCENE); the accelerator is
// the KD tree unless $RT_BENCH_ACCEL says naive or bsp. Wall-clock time.
//   build/release/bench/bench_render --benchmark_min_time=1
#include <cstdlib>
#include <string>

#include "io/load_scene.h"
#include "render_frames.h"

namespace {

void BM_RenderDemo800x600(benchmark::State& state) {
    static const rt::bench::Prepared demo = [] {
        const char* env = std::getenv("RT_BENCH_SCENE");
        // Read as rt-render reads it.
        return rt::bench::prepare(rt::loadScene(env ? env : RT_SOURCE_DIR "/scenes/demo.xml"));
    }();
    rt::bench::renderFrames(state, demo);
}
BENCHMARK(BM_RenderDemo800x600)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
