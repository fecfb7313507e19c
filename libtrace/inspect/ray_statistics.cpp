#include "inspect/ray_statistics.h"

#include <omp.h>

#include "render/integrators/tracer.h"
#include "render/renderer.h"

namespace rt {

double stepsPerRay(const RayCounters& c) { return c.rays ? double(c.traversalSteps) / double(c.rays) : 0.0; }
double testsPerRay(const RayCounters& c) { return c.rays ? double(c.intersectionTests) / double(c.rays) : 0.0; }

RenderCounters traceRayStatistics(const Scene& scene, const Accelerator& accel, const RenderSettings& settings) {
    RenderStats stats;
    render(scene, accel, settings, stats);
    return stats.counters;
}

std::vector<float> pixelWork(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
                             PixelRays rays) {
    RenderSettings traced = settings;
    traced.region.reset();
    if (rays == PixelRays::Camera) {
        traced.shadows = traced.softShadows = traced.glossyReflections = false;
        traced.reflectionDepth = 0;
    }
    validate(traced);
    const Tracer tracer(scene, accel, traced);
    const int width = traced.width, height = traced.height;
    std::vector<float> work(std::size_t(width) * std::size_t(height));
#pragma omp parallel for schedule(dynamic, 4) num_threads(traced.threads > 0 ? traced.threads : omp_get_max_threads())
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            RenderCounters counters;
            tracer.pixel(x, y, counters);
            const RayCounters all = counters.total();
            work[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
                float(all.traversalSteps + all.intersectionTests);
        }
    }
    return work;
}

}  // namespace rt
