// Loading a scene with a 1,000,000-triangle RAW model (issue 2: "a million triangles must
// load in well under a second and under 100 bytes each").
//   build/release/bench/bench_scene_load --benchmark_min_time=0.5
// Counters: bytes per primitive of the flattened scene.primitives (geometry + material
// index) and of the model kept for instancing, and primitives per second.
#include <benchmark/benchmark.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "io/raw_model.h"
#include "io/xml_loader.h"

namespace {

constexpr int kGrid = 1000;  // kGrid x kGrid triangles

// A folder with model.raw (a bumpy 1000 x 1000 grid of triangles) and scene.xml instancing it.
class MillionTriangleScene {
public:
    MillionTriangleScene()
        : dir_(std::filesystem::temp_directory_path() / ("rt-bench-scene-" + std::to_string(getpid()))) {
        std::filesystem::create_directories(dir_);
        rt::Model model;
        model.triangleVertices.reserve(std::size_t(kGrid) * kGrid * 9);
        for (int i = 0; i < kGrid; ++i)
            for (int j = 0; j < kGrid; ++j) {
                const float x = float(i), y = float(j), z = float((i * 7 + j * 13) % 5) * 0.1f;
                model.triangleVertices.insert(model.triangleVertices.end(),
                                              {x, y, z, x + 1, y, z + 0.05f, x, y + 1, z - 0.05f});
            }
        rt::writeRawFile(rawPath(), model);
        std::ofstream(scenePath()) << R"(<?xml version="1.0"?>
<scene>
  <camera fov="60"><origin x="500" y="500" z="-800"/><destination x="500" y="500"/></camera>
  <models><model name="grid" file="model.raw" type="raw"/></models>
  <objects><rotate y="10"><model name="grid"/></rotate></objects>
  <lights><light x="0" y="0" z="-100"/></lights>
</scene>
)";
    }
    ~MillionTriangleScene() { std::filesystem::remove_all(dir_); }
    std::string rawPath() const { return (dir_ / "model.raw").string(); }
    std::string scenePath() const { return (dir_ / "scene.xml").string(); }

private:
    std::filesystem::path dir_;
};

const MillionTriangleScene& testScene() {
    static const MillionTriangleScene scene;
    return scene;
}

void BM_ReadRawModel(benchmark::State& state) {
    const std::string path = testScene().rawPath();
    std::size_t triangles = 0;
    for (auto _ : state) {
        const rt::Model model = rt::readRawFile(path);
        triangles = model.triangleCount();
        benchmark::DoNotOptimize(model.triangleVertices.data());
    }
    state.counters["triangles"] = double(triangles);
    state.counters["triangles/s"] =
        benchmark::Counter(double(triangles), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_ReadRawModel)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_LoadSceneXml(benchmark::State& state) {
    const std::string path = testScene().scenePath();
    double primitives = 0, primitiveBytes = 0, modelBytes = 0;
    for (auto _ : state) {
        const rt::Scene scene = rt::loadSceneXml(path);
        primitives = scene.primitives.size();
        primitiveBytes = double(scene.primitives.memoryBytes());
        modelBytes = double(scene.models.at(0).triangleVertices.capacity() * sizeof(float));
        benchmark::DoNotOptimize(scene.primitives.all<rt::Triangle>().data());
    }
    state.counters["primitives"] = primitives;
    state.counters["bytes/primitive"] = primitiveBytes / primitives;
    state.counters["model bytes/triangle"] = modelBytes / primitives;
    state.counters["primitives/s"] = benchmark::Counter(primitives, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_LoadSceneXml)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
