#include "accel/build.h"

#include "accel/bsp.h"
#include "accel/bvh.h"
#include "accel/kdtree.h"
#include "accel/naive.h"

namespace rt {

std::unique_ptr<Accelerator> buildAccelerator(const Primitives& prims, const AccelSettings& settings) {
    switch (settings.kind) {
        case AccelKind::Naive:
            return std::make_unique<NaiveAccelerator>(prims, settings.triangles);
        case AccelKind::Bsp:
            return buildBspTree(prims, settings.bsp, settings.triangles);
        case AccelKind::Bvh:
            return buildBvh(prims, settings.bvh, settings.triangles);
        case AccelKind::Kd:
            break;
    }
    return buildKdTree(prims, settings.kd, settings.triangles);
}

}  // namespace rt
