#include "accel/naive.h"

namespace rt {

bool NaiveAccelerator::intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const {
    const std::uint32_t n = prims_.size();
    const PrimitiveView prims = view_;  // a local copy, kept in registers (see PrimitiveView)
    counters.intersectionTests += n;
    bool found = false;
    for (std::uint32_t id = 0; id < n; ++id) {
        if (prims.intersect(id, ray, tMax, hit)) {
            tMax = hit.t;
            found = true;
        }
    }
    return found;
}

bool NaiveAccelerator::occluded(const Ray& ray, Real tMax, RayCounters& counters) const {
    const std::uint32_t n = prims_.size();
    const PrimitiveView prims = view_;  // a local copy, kept in registers (see PrimitiveView)
    for (std::uint32_t id = 0; id < n; ++id) {
        ++counters.intersectionTests;
        if (prims.intersectsAny(id, ray, tMax)) return true;
    }
    return false;
}

AccelStats NaiveAccelerator::stats() const {
    AccelStats s;
    s.name = "naive";
    s.primitives = prims_.size();
    s.nodes = 1;
    s.leaves = 1;
    s.primitiveReferences = prims_.size();
    s.averagePrimitivesPerLeaf = prims_.size();
    s.sahCost = prims_.size();  // every ray tests everything (intersection cost 1)
    return s;
}

void NaiveAccelerator::forEachNode(const std::function<void(const TreeNodeInfo&)>& visit) const {
    TreeNodeInfo root;
    root.bounds = prims_.bounds();
    root.primitives = prims_.size();
    visit(root);
}

}  // namespace rt
