// The interface every ray-scene intersection structure implements: the naive list,
// the BSP tree and the KD tree (thesis 3.3.3). Two queries, as in pbrt's aggregates:
// the nearest hit (camera and reflection rays) and any hit closer than a distance
// (shadow rays, which may stop at the first one found).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/aabb.h"
#include "core/ray.h"
#include "geometry/hit_filter.h"
#include "geometry/primitives.h"

namespace rt {

// Work done for rays, counted per thread without locks and summed afterwards.
struct RayCounters {
    std::uint64_t rays = 0;
    std::uint64_t traversalSteps = 0;     // nodes visited
    std::uint64_t intersectionTests = 0;  // ray-primitive tests

    RayCounters& operator+=(const RayCounters& o) {
        rays += o.rays;
        traversalSteps += o.traversalSteps;
        intersectionTests += o.intersectionTests;
        return *this;
    }
};

// What a built structure looks like (thesis Table 4.3 and more).
struct AccelStats {
    std::string name;
    std::uint64_t primitives = 0;  // that the structure was built over
    double buildSeconds = 0;
    int buildThreads = 1;  // that the build ran on
    std::uint64_t nodes = 0;
    std::uint64_t leaves = 0;
    std::uint64_t emptyLeaves = 0;
    std::uint32_t maxDepth = 0;
    double averageLeafDepth = 0;
    double averagePrimitivesPerLeaf = 0;  // over non-empty leaves
    std::uint64_t primitiveReferences = 0;
    std::uint64_t memoryBytes = 0;  // nodes and index arrays, not the primitives
    double sahCost = 0;

    double bytesPerPrimitive() const { return primitives ? double(memoryBytes) / double(primitives) : 0; }
};

// An axis-aligned plane that splits a node of a BSP or KD tree.
struct SplitPlane {
    int axis = 0;       // 0-2
    Real position = 0;  // along the axis
};

// One node of a tree as a tool sees it (rt-inspect's dumps and histograms).
struct TreeNodeInfo {
    std::uint32_t id = 0;     // pre-order index; the root is 0
    std::uint32_t depth = 0;  // the root has depth 0
    Aabb bounds;              // the node's voxel (or, in a bounding volume hierarchy, its box)
    bool leaf = true;
    std::optional<SplitPlane> plane;  // of an inner node of a tree that splits by planes
    std::uint32_t primitives = 0;     // primitive references of a leaf
};

// The most rays Accelerator::intersectPacket and occludedPacket take: eight, as a 4x2 tile of
// pixels or a run of eight.
inline constexpr int kPacketSize = 8;

class Accelerator {
public:
    virtual ~Accelerator() = default;

    // Nearest hit with 0 < t < tMax; fills `hit` and returns true if there is one.
    virtual bool intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const = 0;
    // True if anything is hit with 0 < t < tMax.
    virtual bool occluded(const Ray& ray, Real tMax, RayCounters& counters) const = 0;

    // The nearest hits of `count` (at most kPacketSize) rays, each exactly what intersect()
    // finds for it, bit for bit: found[i] says whether rays[i] hit, and hits[i] is then its hit.
    // Trees trace coherent rays (neighbouring camera rays) together; the default traces one
    // at a time.
    virtual void intersectPacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found,
                                 RayCounters& counters) const {
        for (int i = 0; i < count; ++i) found[i] = intersect(rays[i], tMax, hits[i], counters);
    }
    // Whether each of `count` (at most kPacketSize) rays is blocked, rays[i] before its own
    // tMax[i] (shadow rays, each ending at its light): blocked[i] is what occluded() answers for
    // it, and the counters count what occluded() counts. Trees trace coherent rays (the shadow
    // rays of neighbouring pixels to one light) together; the default traces one at a time.
    virtual void occludedPacket(const Ray* rays, int count, const Real* tMax, bool* blocked,
                                RayCounters& counters) const {
        for (int i = 0; i < count; ++i) blocked[i] = occluded(rays[i], tMax[i], counters);
    }

    virtual AccelStats stats() const = 0;

    // Visits every node in pre-order (a node before its children, the lower child first).
    virtual void forEachNode(const std::function<void(const TreeNodeInfo&)>& visit) const = 0;

    // Hits the filter rejects are skipped by both queries (cut-outs and back faces, geometry/hit_filter.h);
    // none (the default) accepts every hit at no cost. The filter must outlive the queries.
    void setHitFilter(const HitFilter* filter) { filter_ = filter; }

protected:
    const HitFilter* filter_ = nullptr;
};

}  // namespace rt
