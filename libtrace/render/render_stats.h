// Rendering statistics of thesis appendix B and a little more.
#pragma once

#include <cstdint>

#include "accel/accelerator.h"

namespace rt {

// Rays the renderer shot, counted by each thread in its own copy and summed at the end.
struct RenderCounters {
    std::uint64_t primaryRays = 0;
    std::uint64_t shadowRays = 0;
    std::uint64_t reflectionRays = 0;
    RayCounters accel;  // traversal steps and ray-primitive tests of all those rays

    std::uint64_t rays() const { return primaryRays + shadowRays + reflectionRays; }
    RenderCounters& operator+=(const RenderCounters& o) {
        primaryRays += o.primaryRays;
        shadowRays += o.shadowRays;
        reflectionRays += o.reflectionRays;
        accel += o.accel;
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
        const std::uint64_t n = counters.rays();
        return n ? double(counters.accel.intersectionTests) / double(n) : 0.0;
    }
    double raysPerSecond() const { return renderSeconds > 0 ? double(counters.rays()) / renderSeconds : 0.0; }
};

}  // namespace rt
