// SplitTree's queries on the lanes core/simd.h's simdLevel() chooses, by default the widest the CPU
// has: AVX-512, AVX2 or SSE2. The single-ray traversal (kd_single.cpp) and the packet traversal
// (kd_packet.cpp) are each compiled once per level and hold only that level's code; this file,
// compiled once, picks the copy (accel/level_dispatch.h).
#include "accel/level_dispatch.h"
#include "accel/split_tree.h"

namespace rt {

bool SplitTree::intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const {
    Hit nearest;
    nearest.t = tMax;
    const Vec3 invDir = reciprocal(ray.direction);
    Real tMin = 0, tEnd = tMax;
    if (enters(ray, invDir, tMin, tEnd))
        onChosenCopy(leaves_.triangleTest(), [&](auto level, auto test) {
            searchNearest<decltype(level)::value, decltype(test)::value>(ray, invDir, 0, tMin, tEnd, nearest, counters);
        });
    // A hit only ever lowers nearest.t: no flag to keep in the leaf loop.
    if (!(nearest.t < tMax)) return false;
    hit = nearest;
    return true;
}

bool SplitTree::occluded(const Ray& ray, Real tMax, RayCounters& counters) const {
    const Vec3 invDir = reciprocal(ray.direction);
    Real tMin = 0, tEnd = tMax;
    return enters(ray, invDir, tMin, tEnd) && onChosenCopy(leaves_.triangleTest(), [&](auto level, auto test) {
               return searchBlocker<decltype(level)::value, decltype(test)::value>(ray, invDir, 0, tMin, tEnd, tMax,
                                                                                   counters);
           });
}

void SplitTree::intersectPacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found,
                                RayCounters& counters) const {
    onChosenCopy(leaves_.triangleTest(), [&](auto level, auto test) {
        tracePacket<decltype(level)::value, decltype(test)::value>(rays, count, tMax, hits, found, counters);
    });
}

void SplitTree::occludedPacket(const Ray* rays, int count, const Real* tMax, bool* blocked,
                               RayCounters& counters) const {
    onChosenCopy(leaves_.triangleTest(), [&](auto level, auto test) {
        traceShadowPacket<decltype(level)::value, decltype(test)::value>(rays, count, tMax, blocked, counters);
    });
}

}  // namespace rt
