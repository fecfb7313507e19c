// rt's primitives in an Intel Embree 3 scene, for measuring rt's KD tree against it
// (bench/vs_embree). Triangles go to one triangle mesh in float (Embree's precision);
// spheres are user geometry whose callbacks run rt's own sphere test, so both sides
// test spheres alike and only the acceleration structures differ. Primitive ids are
// rt's: a sphere's Embree primID is offset by the triangle count.
#pragma once

#include <embree3/rtcore.h>

#include <atomic>
#include <cstdint>

#include "accel/accelerator.h"
#include "core/ray.h"
#include "geometry/primitives.h"

namespace rt::bench {

// Packets for rtcIntersect8 and rtcOccluded8 are rt's packets (accel/accelerator.h): up to eight rays, traced
// together.
static_assert(kPacketSize == 8);

class EmbreeScene {
public:
    // Builds the BVH at RTC_BUILD_QUALITY_HIGH on `threads` threads. The primitives must
    // outlive the scene (the sphere callbacks read them).
    EmbreeScene(const Primitives& prims, int threads);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    double buildSeconds() const { return buildSeconds_; }
    // Bytes Embree holds after the build (its memory monitor: BVH and geometry buffers),
    // plus rt's sphere array, which the user geometry reads in place of its own copy.
    std::int64_t memoryBytes() const;

    // Nearest hit with 0 <= t < tMax (rtcIntersect1); hit.prim is rt's primitive id.
    bool intersect(const Ray& ray, Real tMax, Hit& hit) const;
    // Any hit with 0 <= t < tMax (rtcOccluded1).
    bool occluded(const Ray& ray, Real tMax) const;
    // Nearest hits of eight rays at once (rtcIntersect8); found[i] says whether hits[i] is set.
    void intersect8(const Ray* rays, Hit* hits, bool* found) const;
    // Whether each of `count` (at most eight) rays is blocked before its tMax[i], all at once (rtcOccluded8).
    void occluded8(const Ray* rays, const Real* tMax, int count, bool* blocked) const;

private:
    const Primitives& prims_;
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    double buildSeconds_ = 0;
    std::atomic<std::int64_t> bytes_{0};  // counted by the device's memory monitor
};

}  // namespace rt::bench
