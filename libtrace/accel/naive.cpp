#include "accel/naive.h"

namespace rt {

// As in the trees: each loop instantiated with the hit filter and without it.
bool NaiveAccelerator::intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const {
    const std::uint32_t n = prims_.size();
    const PrimitiveView prims = view_;  // a local copy, kept in registers (see PrimitiveView)
    counters.intersectionTests += n;
    Hit nearest;
    nearest.t = tMax;
    const auto run = [&](const auto& test) {
        for (std::uint32_t id = 0; id < n; ++id) test(id);
    };
    if (filter_)
        run([&](std::uint32_t id) { intersectFiltered(prims, id, ray, *filter_, nearest); });
    else
        run([&](std::uint32_t id) { prims.intersect(id, ray, nearest.t, nearest); });
    if (!(nearest.t < tMax)) return false;
    hit = nearest;
    return true;
}

bool NaiveAccelerator::occluded(const Ray& ray, Real tMax, RayCounters& counters) const {
    const std::uint32_t n = prims_.size();
    const PrimitiveView prims = view_;  // a local copy, kept in registers (see PrimitiveView)
    const auto run = [&](const auto& test) {
        for (std::uint32_t id = 0; id < n; ++id) {
            ++counters.intersectionTests;
            if (test(id)) return true;
        }
        return false;
    };
    if (filter_) return run([&](std::uint32_t id) { return occludesFiltered(prims, id, ray, tMax, *filter_); });
    return run([&](std::uint32_t id) { return prims.intersectsAny(id, ray, tMax); });
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
