#include "inspect/ray_statistics.h"

#include <algorithm>
#include <cmath>

#include "render/camera_rays.h"

namespace rt {

double stepsPerRay(const RayCounters& c) { return c.rays ? double(c.traversalSteps) / double(c.rays) : 0.0; }
double testsPerRay(const RayCounters& c) { return c.rays ? double(c.intersectionTests) / double(c.rays) : 0.0; }

namespace {

// Secondary rays start this far off the surface along its normal, so that they do not hit
// the surface they leave: relative to the scene's size, as rt-render does (render/tracer.cpp),
// so that both count the same rays.
Real surfaceOffset(const Primitives& prims) {
    constexpr Real kRelative = sizeof(Real) == sizeof(float) ? Real(1e-4) : Real(1e-7);
    const Aabb box = prims.bounds();
    if (box.empty()) return kRelative;
    Real scale = std::max(length(box.diagonal()), Real(1e-3));
    for (int a = 0; a < 3; ++a) scale = std::max({scale, std::abs(box.lo[a]), std::abs(box.hi[a])});
    return kRelative * scale;
}

class RayCounter {
public:
    RayCounter(const Scene& scene, const Accelerator& accel, const RayOptions& options)
        : scene_(scene), accel_(accel), options_(options), offset_(surfaceOffset(scene.primitives)) {}

    // Follows one camera ray and everything it spawns.
    void trace(const Ray& ray, RayStatistics& stats) const { follow(ray, 0, stats); }

private:
    void follow(const Ray& ray, int bounce, RayStatistics& stats) const {
        RayCounters& counters = bounce == 0 ? stats.camera : stats.reflection;
        ++counters.rays;
        Hit hit;
        if (!accel_.intersect(ray, kInfinity, hit, counters)) return;

        const Vec3 p = ray.at(hit.t);
        Vec3 n = scene_.primitives.normal(hit.prim, p);
        if (dot(n, ray.direction) > 0) n = -n;  // the side the ray came from
        const Vec3 origin = p + n * offset_;

        if (options_.shadows) traceShadowRays(p, origin, n, stats.shadow);
        if (bounce < options_.reflectionDepth && reflects(hit.prim)) {
            const Vec3 mirrored = ray.direction - n * (2 * dot(ray.direction, n));
            follow({origin, normalize(mirrored)}, bounce + 1, stats);
        }
    }

    // One shadow ray per light that lies in front of the surface (a light behind it adds
    // nothing to Phong shading, so the renderer need not ask).
    void traceShadowRays(const Vec3& p, const Vec3& origin, const Vec3& n, RayCounters& counters) const {
        for (const Light& light : scene_.lights) {
            if (dot(n, light.position - p) <= 0) continue;
            const Vec3 toLight = light.position - origin;
            const Real distance = length(toLight);
            ++counters.rays;
            accel_.occluded({origin, toLight / distance}, distance, counters);
        }
    }

    bool reflects(std::uint32_t prim) const {
        const std::uint32_t m = scene_.primitives.material(prim);
        return m < scene_.materials.size() && scene_.materials[m].reflection > 0;
    }

    const Scene& scene_;
    const Accelerator& accel_;
    const RayOptions& options_;
    Real offset_;
};

}  // namespace

RayStatistics traceRayStatistics(const Scene& scene, const Accelerator& accel, const RayOptions& options) {
    const CameraRays camera(scene.camera, options.width, options.height);
    const RayCounter counter(scene, accel, options);
    RayStatistics total;
#pragma omp parallel
    {
        RayStatistics local;  // per thread, summed once at the end: no locks in the loop
#pragma omp for schedule(dynamic, 4)
        for (int y = 0; y < options.height; ++y) {
            for (int x = 0; x < options.width; ++x) counter.trace(camera.at(x + Real(0.5), y + Real(0.5)), local);
        }
#pragma omp critical
        total += local;
    }
    return total;
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
