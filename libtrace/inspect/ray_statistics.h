// The work an accelerator does for the rays of one picture: rt-inspect --rays and the
// heat map. The rays are those rt-render traces (thesis 2.1): one camera ray through the
// centre of each pixel; with shadows, one shadow ray from each hit to each light in front
// of the surface; with a reflection depth d, a mirror ray from each hit on a material with
// reflection > 0, recursively, at most d bounces. Shading itself is not computed: only
// which rays exist matters here. The counts are exact and independent of the thread count.
#pragma once

#include <vector>

#include "accel/accelerator.h"
#include "scene/scene.h"

namespace rt {

struct RayOptions {
    int width = 800;   // the thesis's benchmark resolution (thesis 4.3)
    int height = 600;
    bool shadows = false;
    int reflectionDepth = 5;  // maximum number of mirror bounces (rt-render -d, same default)
};

struct RayStatistics {
    RayCounters camera;
    RayCounters shadow;
    RayCounters reflection;

    RayCounters total() const {
        RayCounters t = camera;
        t += shadow;
        t += reflection;
        return t;
    }
    RayStatistics& operator+=(const RayStatistics& o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        return *this;
    }
};

// Work per ray, 0 when there are no rays.
double stepsPerRay(const RayCounters& c);
double testsPerRay(const RayCounters& c);

// Traces the rays of the whole picture through `accel`, which must be built over scene.primitives.
// Throws rt::InputError if the camera is unusable.
RayStatistics traceRayStatistics(const Scene& scene, const Accelerator& accel, const RayOptions& options);

// The work of each pixel's camera ray alone, traversal steps plus intersection tests,
// row-major with row 0 at the top of the image (what the heat map shows).
std::vector<float> cameraRayCost(const Scene& scene, const Accelerator& accel, int width, int height);

}  // namespace rt
