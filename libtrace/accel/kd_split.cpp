#include "accel/kd_split.h"

#include <algorithm>
#include <bit>

namespace rt {

void addEvents(const FloatBox& box, std::uint32_t primitive, int axis, std::vector<SplitEvent>& events) {
    if (box.planar(axis)) {
        events.emplace_back(box.lo[axis], primitive, SplitEvent::Planar);
    } else {
        events.emplace_back(box.lo[axis], primitive, SplitEvent::Start);
        events.emplace_back(box.hi[axis], primitive, SplitEvent::End);
    }
}

namespace {

// A float's bits as an unsigned key in the float's order (negative values flipped
// whole, positive ones get the sign bit set); -0 is made +0, which compares equal.
std::uint32_t orderedKey(float pos) {
    const auto bits = std::bit_cast<std::uint32_t>(pos == 0 ? 0.0f : pos);
    return bits & 0x80000000u ? ~bits : bits | 0x80000000u;
}

// One stable counting-sort pass of `events` by `digit` (values below `buckets`).
template <typename Digit>
void countingPass(std::vector<SplitEvent>& events, std::vector<SplitEvent>& buffer, std::size_t buckets,
                  const Digit& digit) {
    std::vector<std::size_t> start(buckets + 1, 0);
    for (const SplitEvent& e : events) ++start[digit(e) + 1];
    for (std::size_t b = 1; b <= buckets; ++b) start[b] += start[b - 1];
    for (const SplitEvent& e : events) buffer[start[digit(e)]++] = e;
    events.swap(buffer);
}

}  // namespace

// The type first, then the position in three passes of 11 bits: each pass is stable, so
// the last (the position's top bits) decides first and the type last, as operator< does.
void radixSortEvents(std::vector<SplitEvent>& events) {
    std::vector<SplitEvent> buffer(events.size(), SplitEvent(0, 0, SplitEvent::End));
    countingPass(events, buffer, 3, [](const SplitEvent& e) { return std::size_t(e.type()); });
    for (int shift = 0; shift < 32; shift += 11) {
        countingPass(events, buffer, 2048,
                     [shift](const SplitEvent& e) { return std::size_t(orderedKey(e.pos) >> shift) & 2047u; });
    }
}

SahModel::SahModel(const Aabb& voxel, const KdSettings& settings)
    : area_(voxel.surfaceArea()),
      traversalCost_(settings.traversalCost),
      intersectionCost_(settings.intersectionCost),
      emptyBonus_(settings.emptyBonus) {
    areaScale_ = 2 * intersectionCost_ / area_;
    const Vec3 d = voxel.diagonal();
    for (int a = 0; a < 3; ++a) {
        lo_[a] = voxel.lo[a];
        hi_[a] = voxel.hi[a];
        const double other1 = d[(a + 1) % 3], other2 = d[(a + 2) % 3];
        face_[a] = other1 * other2;
        rim_[a] = other1 + other2;
    }
}

// At each position: primitives ending there leave the upper side before the plane is
// evaluated, those starting there join the lower side after it, and those lying in it
// are offered to either side (SahModel::consider).
void sweepSortedEvents(const std::vector<SplitEvent>& events, int axis, std::size_t primitives,
                       const SahModel& sah, SahSplit& best) {
    std::size_t below = 0, above = primitives;
    const std::size_t n = events.size();
    for (std::size_t i = 0; i < n;) {
        const float pos = events[i].pos;
        std::size_t count[3] = {0, 0, 0};
        for (; i < n && events[i].pos == pos; ++i) ++count[events[i].type()];
        const std::size_t ends = count[SplitEvent::End], planars = count[SplitEvent::Planar];
        above -= ends + planars;
        sah.consider(axis, pos, below, above, planars, best);
        below += count[SplitEvent::Start] + planars;
    }
}

SahSplit findSplitBySorting(const std::vector<FloatBox>& boxes, const SahModel& sah) {
    SahSplit best;
    thread_local std::vector<SplitEvent> events;  // reused: small nodes are many
    for (int axis = 0; axis < 3; ++axis) {
        events.clear();
        for (std::uint32_t i = 0; i < boxes.size(); ++i) addEvents(boxes[i], i, axis, events);
        std::sort(events.begin(), events.end());
        sweepSortedEvents(events, axis, boxes.size(), sah, best);
    }
    return best;
}

SahSplit findSplitBySampling(const std::vector<FloatBox>& boxes, const Aabb& voxel, int samples,
                             const SahModel& sah) {
    SahSplit best;
    const std::size_t n = boxes.size();
    std::vector<float> planes;
    std::vector<std::size_t> starts, ends, planars;
    for (int axis = 0; axis < 3; ++axis) {
        planes.clear();
        for (int k = 1; k <= samples; ++k) {
            const float p = float(voxel.lo[axis] + voxel.diagonal()[axis] * k / (samples + 1));
            if (planes.empty() || p > planes.back()) planes.push_back(p);
        }
        const std::size_t m = planes.size();
        starts.assign(m + 1, 0);   // starts[k]: primitives whose first plane with lo < plane is k
        ends.assign(m + 1, 0);     // ends[k]: primitives whose first plane with hi <= plane is k
        planars.assign(m, 0);      // planars[k]: primitives lying in plane k
        for (const FloatBox& b : boxes) {
            ++starts[std::upper_bound(planes.begin(), planes.end(), b.lo[axis]) - planes.begin()];
            const auto end = std::lower_bound(planes.begin(), planes.end(), b.hi[axis]);
            ++ends[end - planes.begin()];
            if (b.planar(axis) && end != planes.end() && *end == b.lo[axis]) ++planars[end - planes.begin()];
        }
        std::size_t started = 0, ended = 0;
        for (std::size_t k = 0; k < m; ++k) {
            started += starts[k];
            ended += ends[k];
            sah.consider(axis, planes[k], started, n - ended, planars[k], best);
        }
    }
    return best;
}

}  // namespace rt
