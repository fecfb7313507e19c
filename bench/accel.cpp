// Accelerator benchmarks (issue 4, thesis 4.3; the BVH, issue 37): tree builds, and the throughput of the
// camera rays and shadow rays of an 800x600 view, on generated scenes of 10k, 100k and
// 1M triangles, 100k spheres, and 100k triangles in a large empty box. Rays are traced on
// one thread, so rays/s (per CPU second) compares the structures, not the machine's core
// count; builds use every OpenMP thread and report real time and the CPU time of all threads.
//
//   build/release/bench/bench_accel --benchmark_filter=Build
//   build/release/bench/bench_accel --benchmark_filter='Rays/tri100k'
//
// The naive list traces every (N/100)-th camera ray only: about 4,800 rays at 10k
// triangles, 48 at 1M, so that each case costs the same ~5e7 intersection tests.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "accel/build.h"
#include "bench_scenes.h"
#include "render/camera_rays.h"

using namespace rt;

namespace {

AccelSettings settingsFor(const std::string& variant) {
    AccelSettings s;
    s.kind = *parseAccelKind(variant.substr(0, variant.find('-')));
    if (variant.find('-') != std::string::npos) s.kd.splitMethod = *parseKdSplitMethod(variant.substr(3));
    return s;
}

// Scenes, trees and rays are made once per process and shared by the cases.
struct Fixture {
    Scene scene;
    std::vector<Ray> cameraRays;
    std::vector<std::pair<Ray, Real>> shadowRays;  // towards the first light, with the distance to it
    std::map<std::string, std::unique_ptr<Accelerator>> trees;

    const Accelerator& tree(const std::string& variant) {
        auto& t = trees[variant];
        if (!t) t = buildAccelerator(scene.primitives, settingsFor(variant));
        return *t;
    }
};

Fixture& fixture(const std::string& sceneName) {
    static std::map<std::string, std::unique_ptr<Fixture>> fixtures;
    auto& f = fixtures[sceneName];
    if (f) return *f;
    f = std::make_unique<Fixture>();
    f->scene = bench::generatedScene(sceneName);
    const CameraRays camera(f->scene.camera, 800, 600);
    for (int y = 0; y < 600; ++y)
        for (int x = 0; x < 800; ++x) f->cameraRays.push_back(camera.at(Real(x) + Real(0.5), Real(y) + Real(0.5)));
    // Shadow rays leave each visible point a little towards the light, as a renderer's do.
    const Accelerator& kd = f->tree("kd");
    const Vec3 light = f->scene.lights.front().position;
    RayCounters counters;
    for (const Ray& ray : f->cameraRays) {
        Hit hit;
        if (!kd.intersect(ray, kInfinity, hit, counters)) continue;
        const Vec3 p = ray.at(hit.t);
        const Real distance = length(light - p);
        const Vec3 d = (light - p) / distance;
        constexpr Real kOffset = Real(1e-4);
        f->shadowRays.push_back({{p + d * kOffset, d}, distance - 2 * kOffset});
    }
    return *f;
}

void reportTree(benchmark::State& state, const AccelStats& s) {
    state.counters["nodes"] = double(s.nodes);
    state.counters["refs/prim"] = double(s.primitiveReferences) / double(s.primitives);
    state.counters["bytes/prim"] = s.bytesPerPrimitive();
    state.counters["sah"] = s.sahCost;
    state.counters["leafDepth"] = s.averageLeafDepth;
}

void reportRays(benchmark::State& state, std::uint64_t rays, const RayCounters& c) {
    state.counters["rays/s"] = benchmark::Counter(double(rays), benchmark::Counter::kIsRate);
    state.counters["tests/ray"] = double(c.intersectionTests) / double(rays);
    state.counters["steps/ray"] = double(c.traversalSteps) / double(rays);
}

void Build(benchmark::State& state, const std::string& sceneName, const std::string& variant) {
    const Scene& scene = fixture(sceneName).scene;
    AccelStats stats;
    for (auto _ : state) {
        const auto tree = buildAccelerator(scene.primitives, settingsFor(variant));
        stats = tree->stats();
    }
    reportTree(state, stats);
    state.counters["prims"] = double(scene.primitives.size());
}

std::size_t naiveStride(const Fixture& f, const std::string& variant) {
    return variant == "naive" ? std::max<std::size_t>(1, f.scene.primitives.size() / 100) : 1;
}

void CameraRays(benchmark::State& state, const std::string& sceneName, const std::string& variant) {
    Fixture& f = fixture(sceneName);
    const Accelerator& tree = f.tree(variant);
    const std::size_t stride = naiveStride(f, variant);
    RayCounters counters;
    std::uint64_t rays = 0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < f.cameraRays.size(); i += stride) {
            Hit hit;
            benchmark::DoNotOptimize(tree.intersect(f.cameraRays[i], kInfinity, hit, counters));
            ++rays;
        }
    }
    reportRays(state, rays, counters);
}

void ShadowRays(benchmark::State& state, const std::string& sceneName, const std::string& variant) {
    Fixture& f = fixture(sceneName);
    const Accelerator& tree = f.tree(variant);
    const std::size_t stride = naiveStride(f, variant);
    RayCounters counters;
    std::uint64_t rays = 0, occluded = 0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < f.shadowRays.size(); i += stride) {
            occluded += tree.occluded(f.shadowRays[i].first, f.shadowRays[i].second, counters);
            ++rays;
        }
    }
    reportRays(state, rays, counters);
    state.counters["occluded"] = double(occluded) / double(rays);
}

// Registered by hand: one case per scene and structure, named Build/<scene>/<structure>.
const bool registered = [] {
    for (const char* scene : {"tri10k", "tri100k", "tri1M", "spheres100k", "stadium100k"}) {
        for (const char* variant : {"bsp", "kd", "bvh"})
            benchmark::RegisterBenchmark((std::string("Build/") + scene + "/" + variant).c_str(), Build, scene, variant)
                ->Unit(benchmark::kMillisecond)
                ->MeasureProcessCPUTime()
                ->UseRealTime();
        for (const char* variant : {"naive", "bsp", "kd", "bvh"}) {
            benchmark::RegisterBenchmark((std::string("CameraRays/") + scene + "/" + variant).c_str(), CameraRays,
                                         scene, variant)
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark((std::string("ShadowRays/") + scene + "/" + variant).c_str(), ShadowRays,
                                         scene, variant)
                ->Unit(benchmark::kMillisecond);
        }
    }
    // The thesis's comparison of split finders (2.5.1), at one size.
    for (const char* variant : {"kd-sort", "kd-sample"}) {
        benchmark::RegisterBenchmark((std::string("Build/tri100k/") + variant).c_str(), Build, "tri100k", variant)
            ->Unit(benchmark::kMillisecond)
            ->MeasureProcessCPUTime()
            ->UseRealTime();
        benchmark::RegisterBenchmark((std::string("CameraRays/tri100k/") + variant).c_str(), CameraRays, "tri100k",
                                     variant)
            ->Unit(benchmark::kMillisecond);
    }
    return true;
}();

}  // namespace
