#include "accel/kd_split.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <utility>

#include "accel/build_chunks.h"
#include "core/simd.h"

namespace rt {

void addEvents(const FloatBox& box, std::uint32_t primitive, int axis, SplitEvents& events) {
    if (box.planar(axis)) {
        events.emplace_back(box.lo[axis], primitive, SplitEvent::Planar);
    } else {
        events.emplace_back(box.lo[axis], primitive, SplitEvent::Start);
        events.emplace_back(box.hi[axis], primitive, SplitEvent::End);
    }
}

void addEventsByType(std::span<const FloatBox> boxes, int axis, SplitEvents& events) {
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

SahSplit findSplitBySorting(std::span<const FloatBox> boxes, const SahModel& sah) {
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

// What the AVX-512 counting (simd_avx512::binSlots) takes for one axis: the guarded planes, -inf
// first and +inf after the last up to kPlanes, and the guess's arithmetic in float.
struct LaneTable {
    static constexpr std::size_t kPlanes = 48;  // three registers of 16
    float planes[kPlanes];
    float base, scale, offset;
    int size;  // the planes between the sentinels
};

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
    // Fills `table` for the AVX-512 counting; false if the planes and sentinels do not fit in it.
    bool fillLaneTable(LaneTable& table) const {
        if (guarded_.size() > LaneTable::kPlanes) return false;
        std::fill(std::copy(guarded_.begin(), guarded_.end(), table.planes), std::end(table.planes),
                  std::numeric_limits<float>::infinity());
        table.base = float(base_);
        table.scale = float(scale_);
        table.offset = float(offset_);
        table.size = int(size_);
        return true;
    }
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

}  // namespace

#if RT_SIMD_AVX512
RT_AVX512_BEGIN
namespace simd_avx512 {

namespace {

// A plane looked up by its index among the guarded planes (-inf first), from three registers that
// hold up to 48 of them: two permutes and a blend instead of a gather.
__m512 planeAt(const __m512 (&table)[3], __m512i j) {
    const __m512 first32 = _mm512_permutex2var_ps(table[0], j, table[1]);
    const __m512 last16 = _mm512_maskz_permutexvar_ps(0xFFFF, j, table[2]);
    return _mm512_mask_blend_ps(_mm512_cmpge_epi32_mask(j, _mm512_set1_epi32(32)), first32, last16);
}

// EvenPlanes::count for 16 bounds: the guess (in float here: only the guess is rounded more), the
// two steps, and then the check that each lane's k has the planes before x below it and the others
// from k on. A lane that fails (its guess was off by more than a step) is set in `unsure`, for the
// scalar search. Before: _CMP_LE_OQ for p <= x (atOrBelow), _CMP_LT_OQ for p < x (below).
// The maskz forms with every lane set: GCC 12's plain ones start from an undefined register, and
// warn that it is uninitialized.
template <int Before>
__m512i countLanes(const __m512 (&table)[3], const LaneTable& lanes, __m512 x, __mmask16& unsure) {
    const __m512i one = _mm512_set1_epi32(1), size = _mm512_set1_epi32(lanes.size);
    const __m512 zero = _mm512_setzero_ps();
    __m512 g = _mm512_mul_ps(_mm512_sub_ps(x, _mm512_set1_ps(lanes.base)), _mm512_set1_ps(lanes.scale));
    g = _mm512_maskz_min_ps(0xFFFF, _mm512_maskz_max_ps(0xFFFF, _mm512_add_ps(g, _mm512_set1_ps(lanes.offset)), zero),
                            _mm512_set1_ps(float(lanes.size)));
    __m512i k = _mm512_maskz_cvttps_epi32(0xFFFF, g);  // plane k is entry k + 1 of the table
    k = _mm512_mask_add_epi32(k, _mm512_cmp_ps_mask(planeAt(table, _mm512_add_epi32(k, one)), x, Before), k, one);
    k = _mm512_mask_sub_epi32(k, _mm512_knot(_mm512_cmp_ps_mask(planeAt(table, k), x, Before)), k, one);
    const __mmask16 finite = _mm512_cmp_ps_mask(_mm512_sub_ps(x, x), zero, _CMP_EQ_OQ);
    const __mmask16 wrong = _mm512_cmp_ps_mask(planeAt(table, _mm512_add_epi32(k, one)), x, Before) |
                            _mm512_knot(_mm512_cmp_ps_mask(planeAt(table, k), x, Before));
    unsure = finite & wrong;
    // As the scalar search: +inf is above every plane, -inf and NaN below them all.
    const __m512i edge = _mm512_maskz_mov_epi32(_mm512_cmp_ps_mask(x, zero, _CMP_GT_OQ), size);
    return _mm512_mask_blend_epi32(finite, edge, k);
}

}  // namespace

// PlaneCounts::addAxis's three slots for 16 boxes on one axis (FloatBox: six floats, lo then hi);
// bit i of the result set where box i needs the scalar search.
static_assert(sizeof(FloatBox) == 6 * sizeof(float) && LaneTable::kPlanes == 3 * 16);
unsigned binSlots(const float* boxes, int axis, const LaneTable& lanes, std::uint32_t* start, std::uint32_t* end,
                  std::uint32_t* planar) {
    const __m512 planes[3] = {_mm512_loadu_ps(lanes.planes), _mm512_loadu_ps(lanes.planes + 16),
                              _mm512_loadu_ps(lanes.planes + 32)};
    const __m512i index =
        _mm512_add_epi32(_mm512_mullo_epi32(_mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15),
                                            _mm512_set1_epi32(6)),
                         _mm512_set1_epi32(axis));
    const __m512 lo = _mm512_mask_i32gather_ps(_mm512_setzero_ps(), 0xFFFF, index, boxes, 4);
    const __m512 hi =
        _mm512_mask_i32gather_ps(_mm512_setzero_ps(), 0xFFFF, _mm512_add_epi32(index, _mm512_set1_epi32(3)), boxes, 4);
    __mmask16 unsureStart, unsureEnd;
    const __m512i first = countLanes<_CMP_LE_OQ>(planes, lanes, lo, unsureStart);
    const __m512i last = countLanes<_CMP_LT_OQ>(planes, lanes, hi, unsureEnd);
    const __mmask16 inPlane =
        _mm512_cmp_ps_mask(lo, hi, _CMP_EQ_OQ) &
        _mm512_cmp_ps_mask(planeAt(planes, _mm512_add_epi32(last, _mm512_set1_epi32(1))), lo, _CMP_EQ_OQ);
    _mm512_storeu_si512(start, first);
    _mm512_storeu_si512(end, last);
    _mm512_storeu_si512(planar, _mm512_mask_blend_epi32(inPlane, _mm512_set1_epi32(lanes.size), last));
    return unsigned(unsureStart | unsureEnd);
}

}  // namespace simd_avx512
RT_AVX512_END
#endif

namespace {

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
#if RT_SIMD_AVX512
        if (simdLevel() == SimdLevel::avx512) {
            tables_.resize(axes.size());
            for (std::size_t a = 0; a < axes.size(); ++a)
                if (!axes[a].planes.fillLaneTable(tables_[a])) {
                    tables_.clear();  // too many planes: the scalar search
                    break;
                }
        }
#endif
    }

    std::uint32_t starts(std::size_t a, std::size_t k) const { return counts_[first_[a] + k]; }
    std::uint32_t ends(std::size_t a, std::size_t k) const { return counts_[first_[a] + stride(a) + k]; }
    std::uint32_t planars(std::size_t a, std::size_t k) const { return counts_[first_[a] + 2 * stride(a) + k]; }

    // Counts boxes[0, n): on AVX-512, 16 at a time per axis (the same slots, so the same counts:
    // the searches' results are exact either way).
    void add(const FloatBox* boxes, std::size_t n) {
        std::size_t i = 0;
#if RT_SIMD_AVX512
        if (!tables_.empty()) {
            alignas(64) std::uint32_t start[16], end[16], planar[16];
            for (; i + 16 <= n; i += 16)
                for (std::size_t a = 0; a < axes_.size(); ++a) {
                    const unsigned unsure =
                        simd_avx512::binSlots(&boxes[i].lo[0], axes_[a].axis, tables_[a], start, end, planar);
                    std::uint32_t* counts = counts_.data() + first_[a];
                    for (int k = 0; k < 16; ++k) {
                        if ((unsure >> k) & 1u) {
                            addAxis(a, boxes[i + std::size_t(k)]);
                            continue;
                        }
                        ++counts[start[k]];
                        ++counts[stride(a) + end[k]];
                        ++counts[2 * stride(a) + planar[k]];
                    }
                }
        }
#endif
        for (; i < n; ++i)
            for (std::size_t a = 0; a < axes_.size(); ++a) addAxis(a, boxes[i]);
    }
    void add(const PlaneCounts& o) {
        for (std::size_t k = 0; k < counts_.size(); ++k) counts_[k] += o.counts_[k];
    }

private:
    std::size_t stride(std::size_t a) const { return axes_[a].planes.size() + 1; }

    void addAxis(std::size_t a, const FloatBox& b) {
        const int axis = axes_[a].axis;
        const EvenPlanes& planes = axes_[a].planes;
        std::uint32_t* counts = counts_.data() + first_[a];
        const std::size_t end = planes.below(b.hi[axis]);
        const bool inPlane = b.planar(axis) && planes[end] == b.lo[axis];
        ++counts[planes.atOrBelow(b.lo[axis])];
        ++counts[stride(a) + end];
        ++counts[2 * stride(a) + (inPlane ? end : planes.size())];
    }

    const std::vector<AxisPlanes>& axes_;
    std::vector<std::size_t> first_;  // per axis, where its counts start
    std::vector<std::uint32_t> counts_;
#if RT_SIMD_AVX512
    std::vector<LaneTable> tables_;  // per axis, for simd_avx512::binSlots; none: the scalar search
#endif
};

// Offers every plane of `axes` to `best`, axis by axis in order, with the boxes below, above
// and in it counted in one pass over the boxes (in chunks on all threads in a large node: the
// counts are integers, so their sum is the same in any order).
SahSplit bestOfPlanes(std::span<const FloatBox> boxes, const std::vector<AxisPlanes>& axes, const SahModel& sah) {
    const std::size_t n = boxes.size();
    const Chunks chunks = nodeChunks(n);
    std::vector<PlaneCounts> counts(chunks.count(), PlaneCounts(axes));  // per chunk
    forEachChunk(chunks, [&](std::size_t c, std::size_t begin, std::size_t end) {
        counts[c].add(boxes.data() + begin, end - begin);
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
FloatBox extentOf(std::span<const FloatBox> boxes) {
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

SahSplit findSplitBySampling(std::span<const FloatBox> boxes, const Aabb& voxel, int samples, const SahModel& sah) {
    std::vector<AxisPlanes> axes;
    for (int axis = 0; axis < 3; ++axis)
        axes.push_back({axis, EvenPlanes(voxel.lo[axis], voxel.diagonal()[axis], samples + 1, 1, samples)});
    return bestOfPlanes(boxes, axes, sah);
}

SahSplit findSplitByBinning(std::span<const FloatBox> boxes, int bins, const SahModel& sah) {
    const FloatBox extent = extentOf(boxes);
    std::vector<AxisPlanes> axes;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = extent.lo[axis], hi = extent.hi[axis];
        if (lo <= hi) axes.push_back({axis, EvenPlanes(lo, hi - lo, bins, 0, bins)});
    }
    return bestOfPlanes(boxes, axes, sah);
}

}  // namespace rt
