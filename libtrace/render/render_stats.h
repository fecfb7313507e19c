// Rendering statistics of thesis appendix B and a little more.
#pragma once

#include <cstdint>

#include "accel/accelerator.h"

namespace rt {

// The rays the renderer shot, by kind, each with the accelerator's work for it (traversal
// steps, ray-primitive tests): what rt-render's statistics and rt-inspect --rays report.
// Each thread counts in its own copy; the copies are summed at the end.
struct RenderCounters {
    RayCounters camera;      // the thesis's primary rays, -S per pixel
    RayCounters shadow;      // towards each light in front of a hit (a bundle for a soft shadow)
    RayCounters reflection;  // mirror and glossy rays, at any depth

    RayCounters total() const {
        RayCounters t = camera;
        t += shadow;
        t += reflection;
        return t;
    }
    std::uint64_t rays() const { return camera.rays + shadow.rays + reflection.rays; }
    RenderCounters& operator+=(const RenderCounters& o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        return *this;
    }
};

struct RenderStats {
    double preprocessSeconds = 0;  // building the accelerator (the thesis's "preprocessing")
    double renderSeconds = 0;      // wall clock of the parallel render
    std::uint64_t objects = 0;     // primitives after flattening
    std::uint64_t lights = 0;
    std::uint64_t treeNodes = 0;
    int threads = 0;
    RenderCounters counters;

    double testsPerRay() const {
        const RayCounters all = counters.total();
        return all.rays ? double(all.intersectionTests) / double(all.rays) : 0.0;
    }
    double raysPerSecond() const { return renderSeconds > 0 ? double(counters.rays()) / renderSeconds : 0.0; }
};

}  // namespace rt
