#include "inspect/ray_statistics.h"

#include "render/camera_rays.h"
#include "render/renderer.h"

namespace rt {

double stepsPerRay(const RayCounters& c) { return c.rays ? double(c.traversalSteps) / double(c.rays) : 0.0; }
double testsPerRay(const RayCounters& c) { return c.rays ? double(c.intersectionTests) / double(c.rays) : 0.0; }

RenderCounters traceRayStatistics(const Scene& scene, const Accelerator& accel, const RenderSettings& settings) {
    RenderStats stats;
    render(scene, accel, settings, stats);
    return stats.counters;
}

std::vector<float> cameraRayCost(const Scene& scene, const Accelerator& accel, int width, int height) {
    const CameraRays camera(scene.camera, width, height);
    std::vector<float> cost(std::size_t(width) * std::size_t(height));
#pragma omp parallel for schedule(dynamic, 4)
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            RayCounters counters;
            Hit hit;
            accel.intersect(camera.at(x + Real(0.5), y + Real(0.5)), kInfinity, hit, counters);
            cost[std::size_t(y) * width + x] = float(counters.traversalSteps + counters.intersectionTests);
        }
    }
    return cost;
}

}  // namespace rt
