// One frame of a thesis scene (Table 4.1), as bench_render times it (render_frames.h), with the
// scene made in memory by scene/thesis_scenes.h: ships unless $RT_BENCH_THESIS_SCENE names
// another; the KD tree unless $RT_BENCH_ACCEL says naive or bsp.
//   build/release/bench/bench_thesis_frame --benchmark_filter=/threads:1/
// Table 4.5 (bench/thesis_tables.sh) builds it with eight compilers and flag sets, so it compiles
// only what the frame runs (bench/CMakeLists.txt): not the importers, OpenImageIO and XML code that
// reading a scene file brings, which took two thirds of each build's CPU time and are not what the
// table measures. The scene is the one `rt-convert --generate` writes: the rays, pixels and
// instructions of the frame are those of bench_render on that file.
#include <cstdlib>

#include "render_frames.h"
#include "scene/thesis_scenes.h"

namespace {

void BM_ThesisFrame800x600(benchmark::State& state) {
    static const rt::bench::Prepared thesis = [] {
        const char* name = std::getenv("RT_BENCH_THESIS_SCENE");
        return rt::bench::prepare(rt::thesisScene(name ? name : "ships"));
    }();
    rt::bench::renderFrames(state, thesis);
}
BENCHMARK(BM_ThesisFrame800x600)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
