// Finding the SAH split of a KD node (thesis 2.5.1). The three methods of KdSplitMethod
// share the cost model and the sweep over sorted plane events; they differ in where the
// sorted events come from (kept sorted from the root by the builder for Sweep, sorted in
// every node for Sort) or in evaluating only a few evenly spaced planes (Sample, and the
// binning that Sweep uses in its largest nodes).
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "accel/settings.h"
#include "core/aabb.h"
#include "core/default_init.h"

namespace rt {

// A primitive's bounds clipped to a node's voxel. Floats: the builder rounds the clipped
// bounds outwards to float, so every candidate plane is a value a node can store.
struct FloatBox {
    float lo[3], hi[3];

    // The box of no points (lo above hi on every axis), which include() grows.
    static FloatBox empty() {
        constexpr float inf = std::numeric_limits<float>::infinity();
        return {{inf, inf, inf}, {-inf, -inf, -inf}};
    }
    void include(const FloatBox& b) {
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = std::min(lo[axis], b.lo[axis]);
            hi[axis] = std::max(hi[axis], b.hi[axis]);
        }
    }

    bool planar(int axis) const { return lo[axis] == hi[axis]; }
    // Which children of the plane `pos` on `axis` the primitive goes to. One lying in the
    // plane goes to one side only, the side the split chose (Wald and Havran 2006): a ray
    // crossing the plane meets it at the plane's distance from either side, and a ray in
    // the plane or starting on it cannot hit it (Moller-Trumbore gives det = 0 or t = 0).
    bool inPlane(int axis, float pos) const { return lo[axis] == pos && hi[axis] == pos; }
    bool below(int axis, float pos, bool planarBelow) const {
        return lo[axis] < pos || (planarBelow && inPlane(axis, pos));
    }
    bool above(int axis, float pos, bool planarBelow) const {
        return hi[axis] > pos || (!planarBelow && inPlane(axis, pos));
    }
};

// Where a primitive's clipped bounds start or end along one axis (Wald and Havran 2006,
// thesis [12]). Sorted by position, then ends before planars before starts.
struct SplitEvent {
    enum Type : std::uint32_t { End = 0, Planar = 1, Start = 2 };

    float pos;
    std::uint32_t code;  // (local primitive index << 2) | type

    SplitEvent() = default;
    SplitEvent(float p, std::uint32_t primitive, Type type) : pos(p), code((primitive << 2) | type) {}
    std::uint32_t primitive() const { return code >> 2; }
    Type type() const { return Type(code & 3u); }
    bool operator<(const SplitEvent& o) const { return pos < o.pos || (pos == o.pos && type() < o.type()); }
};

using SplitEvents = UninitializedVector<SplitEvent>;  // sized first, then written

// Sorts events into operator<'s order in linear time (LSD radix sort), for the root's
// millions of events; std::sort serves the small lists below it. Faster when the events
// already come in type order (addEventsByType).
void radixSortEvents(SplitEvents& events);

// Merges the sorted lists [a, aEnd) and [b, bEnd) into `out` (std::merge: equal events from
// `a` first), without a branch per event: which list comes next is as good as random, and a
// mispredicted branch cost more than the merge's work.
void mergeSortedEvents(const SplitEvent* a, const SplitEvent* aEnd, const SplitEvent* b, const SplitEvent* bEnd,
                       SplitEvent* out);

// Appends the events of one primitive's bounds on `axis`.
void addEvents(const FloatBox& box, std::uint32_t primitive, int axis, SplitEvents& events);
// Appends the events of all `boxes` (primitive i is boxes[i]) on `axis` in type order: ends,
// then planars, then starts, each in primitive order.
void addEventsByType(std::span<const FloatBox> boxes, int axis, SplitEvents& events);

struct SahSplit {
    int axis = -1;
    float pos = 0;
    double cost = std::numeric_limits<double>::infinity();
    bool planarBelow = true;  // primitives lying in the plane go below (else above)
};

// Cost of splitting a voxel, K = C_T + C_I (S_A/S_V N_A + S_B/S_V N_B) (thesis 2.5.1),
// times the empty-space bonus when one side holds nothing (Wald and Havran 2006).
class SahModel {
public:
    SahModel(const Aabb& voxel, const KdSettings& settings);

    double leafCost(std::size_t primitives) const { return intersectionCost_ * double(primitives); }
    bool degenerate() const { return !(area_ > 0); }
    // Keeps the cheaper of `best` and the plane `pos`, given the primitives wholly below
    // and above it and those lying in it, which go to the cheaper side. Planes on the
    // voxel's faces cut nothing off and are ignored. A child of extent e along the axis
    // has area 2 (face + e rim). Inline: the sweep calls it for every event position.
    void consider(int axis, float pos, std::size_t below, std::size_t above, std::size_t inPlane,
                  SahSplit& best) const {
        if (!(pos > lo_[axis] && pos < hi_[axis])) return;
        const double belowArea = face_[axis] + (pos - lo_[axis]) * rim_[axis];
        const double aboveArea = face_[axis] + (hi_[axis] - pos) * rim_[axis];
        offer({axis, pos, cost(belowArea, aboveArea, below + inPlane, above), true}, best);
        if (inPlane > 0) offer({axis, pos, cost(belowArea, aboveArea, below, above + inPlane), false}, best);
    }

private:
    double cost(double belowArea, double aboveArea, std::size_t below, std::size_t above) const {
        const double k = traversalCost_ + areaScale_ * (belowArea * double(below) + aboveArea * double(above));
        return below == 0 || above == 0 ? k * emptyBonus_ : k;
    }
    static void offer(const SahSplit& candidate, SahSplit& best) {
        if (candidate.cost < best.cost) best = candidate;
    }

    double lo_[3], hi_[3];
    double face_[3], rim_[3];  // per split axis: area of the face across it, and its perimeter / 2
    double area_;
    double areaScale_;  // 2 C_I / area: turns (face + e rim) N into C_I P N
    double traversalCost_, intersectionCost_, emptyBonus_;
};

// One pass over the sorted events of `axis` evaluates every candidate plane there.
void sweepSortedEvents(const SplitEvents& events, int axis, std::size_t primitives, const SahModel& sah,
                       SahSplit& best);

// The thesis's method: build and sort the events of every axis in this node.
SahSplit findSplitBySorting(std::span<const FloatBox> boxes, const SahModel& sah);

// The thesis's sampling: `samples` evenly spaced planes per axis inside the voxel.
SahSplit findSplitBySampling(std::span<const FloatBox> boxes, const Aabb& voxel, int samples, const SahModel& sah);

// Min-max binning (Shevtsov et al. 2007): `bins` + 1 evenly spaced planes per axis from the
// lowest lower bound of the boxes to the highest upper bound, so that the planes at both ends
// cut off the empty space around them, as the exact sweep's would.
SahSplit findSplitByBinning(std::span<const FloatBox> boxes, int bins, const SahModel& sah);

}  // namespace rt
