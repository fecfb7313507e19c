#include "accel/naive.h"

#include "geometry/watertight_triangle.h"

namespace rt {

namespace {

// The list's primitives for one ray with its triangles tested watertight (geometry/
// watertight_triangle.h), the sheared ray found once; the other kinds as PrimitiveView tests them.
class WatertightView {
public:
    WatertightView(const PrimitiveView& prims, const std::vector<Triangle>& triangles, const Ray& ray)
        : prims_(prims), triangles_(triangles.data()), triangleCount_(std::uint32_t(triangles.size())), sheared_(ray) {}

    // As PrimitiveView's: the triangles come first among the ids.
    bool intersect(std::uint32_t id, const Ray& ray, Real tMax, Hit& hit) const {
        if (id >= triangleCount_) return prims_.intersect(id, ray, tMax, hit);
        if (!intersectWatertight(triangles_[id], sheared_, tMax, hit)) return false;
        hit.prim = id;
        return true;
    }
    bool intersectsAny(std::uint32_t id, const Ray& ray, Real tMax) const {
        Hit hit;
        return intersect(id, ray, tMax, hit);
    }

private:
    PrimitiveView prims_;
    const Triangle* triangles_;
    std::uint32_t triangleCount_;
    ShearedRay sheared_;
};

// As in the trees: each loop instantiated with the hit filter and without it. `prims` is a
// PrimitiveView or a WatertightView.
template <class View>
Hit nearestOf(const View& prims, std::uint32_t n, const Ray& ray, Real tMax, const HitFilter* filter) {
    Hit nearest;
    nearest.t = tMax;
    const auto run = [&](const auto& test) {
        for (std::uint32_t id = 0; id < n; ++id) test(id);
    };
    if (filter)
        run([&](std::uint32_t id) { intersectFiltered(prims, id, ray, *filter, nearest); });
    else
        run([&](std::uint32_t id) { prims.intersect(id, ray, nearest.t, nearest); });
    return nearest;
}

template <class View>
bool anyOf(const View& prims, std::uint32_t n, const Ray& ray, Real tMax, const HitFilter* filter,
           RayCounters& counters) {
    const auto run = [&](const auto& test) {
        for (std::uint32_t id = 0; id < n; ++id) {
            ++counters.intersectionTests;
            if (test(id)) return true;
        }
        return false;
    };
    if (filter) return run([&](std::uint32_t id) { return occludesFiltered(prims, id, ray, tMax, *filter); });
    return run([&](std::uint32_t id) { return prims.intersectsAny(id, ray, tMax); });
}

}  // namespace

bool NaiveAccelerator::intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const {
    const std::uint32_t n = prims_.size();
    const PrimitiveView prims = view_;  // a local copy, kept in registers (see PrimitiveView)
    counters.intersectionTests += n;
    const Hit nearest = triangles_ == TriangleTest::Watertight
                            ? nearestOf(WatertightView(prims, prims_.all<Triangle>(), ray), n, ray, tMax, filter_)
                            : nearestOf(prims, n, ray, tMax, filter_);
    if (!(nearest.t < tMax)) return false;
    hit = nearest;
    return true;
}

bool NaiveAccelerator::occluded(const Ray& ray, Real tMax, RayCounters& counters) const {
    const std::uint32_t n = prims_.size();
    const PrimitiveView prims = view_;  // a local copy, kept in registers (see PrimitiveView)
    if (triangles_ == TriangleTest::Watertight)
        return anyOf(WatertightView(prims, prims_.all<Triangle>(), ray), n, ray, tMax, filter_, counters);
    return anyOf(prims, n, ray, tMax, filter_, counters);
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
