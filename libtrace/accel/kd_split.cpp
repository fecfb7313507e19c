#include "accel/kd_split.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <utility>

#include "accel/build_chunks.h"

namespace rt {

void addEvents(const FloatBox& box, std::uint32_t primitive, int axis, SplitEvents& events) {
    if (box.planar(axis)) {
        events.emplace_back(box.lo[axis], primitive, SplitEvent::Planar);
    } else {
        events.emplace_back(box.lo[axis], primitive, SplitEvent::Start);
        events.emplace_back(box.hi[axis], primitive, SplitEvent::End);
    }
}

void addEventsByType(const std::vector<FloatBox>& boxes, int axis, SplitEvents& events) {
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        if (!boxes[i].planar(axis)) events.emplace_back(boxes[i].hi[axis], i, SplitEvent::End);
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        if (boxes[i].planar(axis)) events.emplace_back(boxes[i].lo[axis], i, SplitEvent::Planar);
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        if (!boxes[i].planar(axis)) events.emplace_back(boxes[i].lo[axis], i, SplitEvent::Start);
}

namespace {

// A float's bits as an unsigned key in the float's order (negative values flipped
// whole, positive ones get the sign bit set); -0 is made +0, which compares equal.
std::uint32_t orderedKey(float pos) {
    const auto bits = std::bit_cast<std::uint32_t>(pos == 0 ? 0.0f : pos);
    return bits & 0x80000000u ? ~bits : bits | 0x80000000u;
}

bool typeBefore(const SplitEvent& a, const SplitEvent& b) { return a.type() < b.type(); }

// One stable counting-sort pass of `events` by `digit`, given the digit's histogram.
template <typename Digit>
void countingPass(SplitEvents& events, SplitEvents& buffer, std::vector<std::size_t> start, const Digit& digit) {
    std::size_t sum = 0;
    for (std::size_t& s : start) sum += std::exchange(s, sum);
    for (const SplitEvent& e : events) buffer[start[digit(e)]++] = e;
    events.swap(buffer);
}

}  // namespace

// The type first, then the position in three passes of 11 bits: each pass is stable, so
// the last (the position's top bits) decides first and the type last, as operator< does.
// The root's millions of events do not fit in the caches, so every pass over them counts:
// the type pass is skipped when the events already come in type order (the root's do,
// addEventsByType), and one read counts the digits of all three position passes.
void radixSortEvents(SplitEvents& events) {
    SplitEvents buffer(events.size());
    if (!std::is_sorted(events.begin(), events.end(), typeBefore)) {
        std::vector<std::size_t> types(3, 0);
        for (const SplitEvent& e : events) ++types[e.type()];
        countingPass(events, buffer, std::move(types), [](const SplitEvent& e) { return std::size_t(e.type()); });
    }
    constexpr int kBits = 11, kPasses = 3;
    constexpr std::uint32_t kMask = (1u << kBits) - 1;
    std::vector<std::size_t> histograms[kPasses];
    for (std::vector<std::size_t>& h : histograms) h.assign(kMask + 1, 0);
    for (const SplitEvent& e : events) {
        const std::uint32_t key = orderedKey(e.pos);
        for (int p = 0; p < kPasses; ++p) ++histograms[p][(key >> (p * kBits)) & kMask];
    }
    for (int p = 0; p < kPasses; ++p) {
        const int shift = p * kBits;
        countingPass(events, buffer, std::move(histograms[p]),
                     [shift](const SplitEvent& e) { return std::size_t(orderedKey(e.pos) >> shift) & kMask; });
    }
}

void mergeSortedEvents(const SplitEvent* a, const SplitEvent* aEnd, const SplitEvent* b, const SplitEvent* bEnd,
                       SplitEvent* out) {
    while (a != aEnd && b != bEnd) {
        // operator< with & and | for && and ||, and a pointer chosen by a conditional move
        const bool takeB = (b->pos < a->pos) | ((b->pos == a->pos) & (b->type() < a->type()));
        *out++ = *(takeB ? b : a);
        b += takeB;
        a += !takeB;
    }
    std::copy(b, bEnd, std::copy(a, aEnd, out));
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
void sweepSortedEvents(const SplitEvents& events, int axis, std::size_t primitives, const SahModel& sah,
                       SahSplit& best) {
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
    thread_local SplitEvents events;  // reused: small nodes are many
    for (int axis = 0; axis < 3; ++axis) {
        events.clear();
        for (std::uint32_t i = 0; i < boxes.size(); ++i) addEvents(boxes[i], i, axis, events);
        std::sort(events.begin(), events.end());
        sweepSortedEvents(events, axis, boxes.size(), sah, best);
    }
    return best;
}

namespace {

// The planes base + extent k / divisions for k = first..last, rounded to float, without
// repeats. A bound's place among them is guessed by arithmetic and then corrected against the
// planes themselves, so it is exact: a step each way without a branch (the planes sit between
// two sentinels, -inf and +inf, so that the step may look one past either end), then loops for
// a guess off by more, which the rounding of the planes leaves rare. The binned nodes are the
// largest, and their boxes many: a binary search, or a mispredicted branch, per bound cost more
// than the counting.
class EvenPlanes {
public:
    EvenPlanes(double base, double extent, int divisions, int first, int last)
        : base_(base), scale_(extent > 0 ? divisions / extent : 0), offset_(1 - first) {
        constexpr float inf = std::numeric_limits<float>::infinity();
        guarded_.push_back(-inf);
        for (int k = first; k <= last; ++k) {
            const float p = float(base + extent * k / divisions);
            if (guarded_.size() == 1 || p > guarded_.back()) guarded_.push_back(p);
        }
        size_ = guarded_.size() - 1;
        guarded_.push_back(inf);
    }

    std::size_t size() const { return size_; }
    float operator[](std::size_t k) const { return guarded_[k + 1]; }
    // The number of planes p <= x (std::upper_bound's index).
    std::size_t atOrBelow(float x) const {
        return count(x, [x](float p) { return p <= x; });
    }
    // The number of planes p < x (std::lower_bound's index).
    std::size_t below(float x) const {
        return count(x, [x](float p) { return p < x; });
    }

private:
    // The k with before(plane k - 1) and !before(plane k): the planes before x are a prefix.
    template <typename Before>
    std::size_t count(float x, const Before& before) const {
        if (!std::isfinite(x)) return x > 0 ? size_ : 0;              // +inf is above every plane; -inf and NaN none
        const float* plane = guarded_.data() + 1;                     // plane[-1] = -inf, plane[size_] = +inf
        const double guess = (double(x) - base_) * scale_ + offset_;  // clamped to [0, size_] below
        std::size_t k = guess > 0 ? (guess < double(size_) ? std::size_t(guess) : size_) : 0;
        // For a finite x the sentinels stop every step and loop within [0, size_].
        k += std::size_t(before(plane[k]));
        k -= std::size_t(!before(plane[k - 1]));
        while (before(plane[k])) ++k;
        while (!before(plane[k - 1])) --k;
        return k;
    }

    double base_, scale_, offset_;
    std::size_t size_;
    std::vector<float> guarded_;
};

struct AxisPlanes {
    int axis;
    EvenPlanes planes;
};

// How many boxes start, end and lie in each plane of each axis's EvenPlanes: starts[k] counts
// the boxes whose first plane above their lower bound is k, ends[k] those whose first plane at
// or above their upper bound is k, planars[k] those lying in plane k (a planar box lying in no
// plane is counted in an unused last slot, so that no branch decides). One array of 32-bit
// counts per axis.
class PlaneCounts {
public:
    explicit PlaneCounts(const std::vector<AxisPlanes>& axes) : axes_(axes) {
        for (const AxisPlanes& a : axes) {
            first_.push_back(counts_.size());
            counts_.resize(counts_.size() + 3 * (a.planes.size() + 1), 0);
        }
    }

    std::uint32_t starts(std::size_t a, std::size_t k) const { return counts_[first_[a] + k]; }
    std::uint32_t ends(std::size_t a, std::size_t k) const { return counts_[first_[a] + stride(a) + k]; }
    std::uint32_t planars(std::size_t a, std::size_t k) const { return counts_[first_[a] + 2 * stride(a) + k]; }

    void add(const FloatBox& b) {
        for (std::size_t a = 0; a < axes_.size(); ++a) {
            const int axis = axes_[a].axis;
            const EvenPlanes& planes = axes_[a].planes;
            std::uint32_t* counts = counts_.data() + first_[a];
            const std::size_t end = planes.below(b.hi[axis]);
            const bool inPlane = b.planar(axis) && planes[end] == b.lo[axis];
            ++counts[planes.atOrBelow(b.lo[axis])];
            ++counts[stride(a) + end];
            ++counts[2 * stride(a) + (inPlane ? end : planes.size())];
        }
    }
    void add(const PlaneCounts& o) {
        for (std::size_t k = 0; k < counts_.size(); ++k) counts_[k] += o.counts_[k];
    }

private:
    std::size_t stride(std::size_t a) const { return axes_[a].planes.size() + 1; }

    const std::vector<AxisPlanes>& axes_;
    std::vector<std::size_t> first_;  // per axis, where its counts start
    std::vector<std::uint32_t> counts_;
};

// Offers every plane of `axes` to `best`, axis by axis in order, with the boxes below, above
// and in it counted in one pass over the boxes (in chunks on all threads in a large node: the
// counts are integers, so their sum is the same in any order).
SahSplit bestOfPlanes(const std::vector<FloatBox>& boxes, const std::vector<AxisPlanes>& axes, const SahModel& sah) {
    const std::size_t n = boxes.size();
    const Chunks chunks = nodeChunks(n);
    std::vector<PlaneCounts> counts(chunks.count(), PlaneCounts(axes));  // per chunk
    forEachChunk(chunks, [&](std::size_t c, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) counts[c].add(boxes[i]);
    });
    for (std::size_t c = 1; c < counts.size(); ++c) counts[0].add(counts[c]);
    SahSplit best;
    for (std::size_t a = 0; a < axes.size(); ++a) {
        std::size_t started = 0, ended = 0;
        for (std::size_t k = 0; k < axes[a].planes.size(); ++k) {
            started += counts[0].starts(a, k);
            ended += counts[0].ends(a, k);
            sah.consider(axes[a].axis, axes[a].planes[k], started, n - ended, counts[0].planars(a, k), best);
        }
    }
    return best;
}

// The lowest lower and highest upper bound of the boxes on each axis (empty: lo > hi).
FloatBox extentOf(const std::vector<FloatBox>& boxes) {
    const Chunks chunks = nodeChunks(boxes.size());
    std::vector<FloatBox> extents(chunks.count(), FloatBox::empty());
    forEachChunk(chunks, [&](std::size_t c, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) extents[c].include(boxes[i]);
    });
    FloatBox extent = FloatBox::empty();
    for (const FloatBox& e : extents) extent.include(e);
    return extent;
}

}  // namespace

SahSplit findSplitBySampling(const std::vector<FloatBox>& boxes, const Aabb& voxel, int samples, const SahModel& sah) {
    std::vector<AxisPlanes> axes;
    for (int axis = 0; axis < 3; ++axis)
        axes.push_back({axis, EvenPlanes(voxel.lo[axis], voxel.diagonal()[axis], samples + 1, 1, samples)});
    return bestOfPlanes(boxes, axes, sah);
}

SahSplit findSplitByBinning(const std::vector<FloatBox>& boxes, int bins, const SahModel& sah) {
    const FloatBox extent = extentOf(boxes);
    std::vector<AxisPlanes> axes;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = extent.lo[axis], hi = extent.hi[axis];
        if (lo <= hi) axes.push_back({axis, EvenPlanes(lo, hi - lo, bins, 0, bins)});
    }
    return bestOfPlanes(boxes, axes, sah);
}

}  // namespace rt
