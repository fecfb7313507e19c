// A test a candidate hit must pass before an accelerator accepts it: the scene's materials
// (render/material_filter.h) reject hits where a cut-out's opacity is below the cut-off and
// hits on the back of a single-sided surface as the ray's source sees it (a shadow ray's is the
// light: Ray::shadow), so rays of both queries (nearest hit and any hit) pass through leaves,
// fences and back faces as if they were not there. The ray, flag included, is all a filter
// needs to know about the query: the accelerators pass it on unchanged. It is defined
// here, outside accel/, so that the accelerators only call it. Scenes without such materials
// set no filter, and the leaf loops then run without it.
#pragma once

#include "geometry/primitives.h"

namespace rt {

class HitFilter {
public:
    virtual ~HitFilter() = default;
    // Whether `hit` (t, prim, and the primitive's u, v) of `ray` counts. Thread-safe.
    virtual bool accepts(const Ray& ray, const Hit& hit) const = 0;
};

// The leaf tests with a filter, on a PrimitiveView (or a view with its intersect, as the naive
// list's with watertight triangles). The nearest hit: primitive `id`'s hit nearer than nearest.t
// replaces `nearest` only if the filter accepts it.
template <class View>
void intersectFiltered(const View& prims, std::uint32_t id, const Ray& ray, const HitFilter& filter, Hit& nearest) {
    Hit candidate;
    if (prims.intersect(id, ray, nearest.t, candidate) && filter.accepts(ray, candidate)) nearest = candidate;
}
// Any hit (shadow rays): the primitive's nearest hit before tMax, if the filter accepts it. A
// triangle is hit once; of a closed primitive's two hits the nearer decides.
template <class View>
bool occludesFiltered(const View& prims, std::uint32_t id, const Ray& ray, Real tMax, const HitFilter& filter) {
    Hit candidate;
    return prims.intersect(id, ray, tMax, candidate) && filter.accepts(ray, candidate);
}

}  // namespace rt
