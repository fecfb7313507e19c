#include "accel/kdtree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "accel/kd_split.h"
#include "accel/tree_builder.h"
#include "core/stopwatch.h"
#include "geometry/clip.h"

namespace rt {

int defaultKdMaxDepth(std::size_t primitives) {
    return int(std::lround(8 + 1.3 * std::log2(double(std::max<std::size_t>(primitives, 1)))));
}

int kdMaxDepth(const KdSettings& settings, std::size_t primitives) {
    return std::clamp(settings.maxDepth.value_or(defaultKdMaxDepth(primitives)), 0, kMaxTreeDepth);
}

namespace {

// Below this many primitives a node finds its split by sorting its own events, as the
// Sort method does: the same split (kd_split.h) without carrying sorted events down.
// Measured: 10% less build time than 32, and no worse than carrying them to the leaves.
constexpr std::size_t kSweepMinimum = 8;

// The primitive references all leaves of a tree may hold, per primitive of the scene. A split
// copies the primitives that straddle its plane into both children; adversarial scenes (large
// triangles over a cluster of tiny ones) make the SAH split on and on, to millions of nodes
// for 40,000 triangles. The budget is shared out top-down in proportion to the children's
// references, so a path that keeps duplicating runs out and ends in a leaf, while the tree
// stays the same for any number of threads. Real scenes stay far below it (docs/trees.md).
constexpr double kReferenceBudgetPerPrimitive = 16;

// Whether a node finds its split by sweeping sorted events that it carries (and hands on
// to its children): those of the Sweep method between the sizes that sort their own events
// and those that bin (KdSettings::binningMinimum).
bool carriesEvents(const KdSettings& settings, std::size_t primitives) {
    return settings.splitMethod == KdSplitMethod::Sweep && primitives >= kSweepMinimum &&
           primitives < settings.binningMinimum;
}

bool bins(const KdSettings& settings, std::size_t primitives) {
    return settings.splitMethod == KdSplitMethod::Sweep && primitives >= settings.binningMinimum;
}

struct KdNode {
    // Sized and then written (sortToSides, makeRoot): not zeroed first, a pass over memory saved.
    UninitializedVector<std::uint32_t> primitives;  // ids into Primitives
    UninitializedVector<FloatBox> boxes;            // their bounds clipped to the voxel
    std::array<SplitEvents, 3> events;              // Sweep only: per axis, sorted, indices into `primitives`
    Aabb voxel;
    int depth = 0;
    double referenceBudget = 0;  // references the leaves of this subtree may hold at most
};

// Bounds rounded outwards to float, then kept inside the (float-valued) voxel.
FloatBox toFloatBox(const Aabb& b, const Aabb& voxel) {
    FloatBox f;
    for (int a = 0; a < 3; ++a) {
        f.lo[a] = std::max(floatBelow(b.lo[a]), float(voxel.lo[a]));
        f.hi[a] = std::min(floatAbove(b.hi[a]), float(voxel.hi[a]));
    }
    return f;
}

class KdSplitter {
public:
    KdSplitter(const Primitives& prims, const KdSettings& settings)
        : prims_(prims),
          settings_(settings),
          maxDepth_(kdMaxDepth(settings, prims.size())),
          rootArea_(roundOutToFloat(prims.bounds()).surfaceArea()) {}

    std::optional<Partition<KdNode>> operator()(KdNode& node) const {
        const std::size_t n = node.primitives.size();
        if (n == 0 || node.depth >= maxDepth_) return std::nullopt;
        const SahModel sah(node.voxel, settings_);
        if (sah.degenerate()) return std::nullopt;
        const SahSplit best = findSplit(node, sah);
        if (best.axis < 0 || best.cost >= sah.leafCost(n)) return std::nullopt;  // no plane beats the leaf
        if (gain(node, sah.leafCost(n) - best.cost) < settings_.minimumGain) return std::nullopt;
        Partition<KdNode> parts = partition(node, best);
        if (!shareBudget(node.referenceBudget, parts.below, parts.above)) return std::nullopt;
        return parts;
    }

private:
    // What splitting `node` saves a ray entering the root, by the SAH, when the split costs
    // `saving` less than the leaf (the node's area is not 0, so neither is the root's).
    double gain(const KdNode& node, double saving) const { return saving * node.voxel.surfaceArea() / rootArea_; }

    SahSplit findSplit(KdNode& node, const SahModel& sah) const {
        const std::size_t n = node.primitives.size();
        if (settings_.splitMethod == KdSplitMethod::Sample)
            return findSplitBySampling(node.boxes, node.voxel, settings_.samples, sah);
        if (bins(settings_, n)) return findSplitByBinning(node.boxes, settings_.bins, sah);
        if (!carriesEvents(settings_, n)) return findSplitBySorting(node.boxes, sah);
        if (node.events[0].empty()) sortEvents(node);  // the root, or a child of a binned node
        SahSplit best;
        for (int axis = 0; axis < 3; ++axis) sweepSortedEvents(node.events[axis], axis, n, sah, best);
        return best;
    }

    // The three axes on three threads in a large node (a root that carries events, when
    // binningMinimum is above its size).
    static void sortEvents(KdNode& node) {
        forEachChunk(nodeChunks(3, 1, node.boxes.size()), [&](std::size_t, std::size_t begin, std::size_t end) {
            for (std::size_t axis = begin; axis < end; ++axis) {
                SplitEvents& events = node.events[axis];
                events.reserve(2 * node.boxes.size());
                addEventsByType(node.boxes, int(axis), events);  // spares radixSortEvents its type pass
                radixSortEvents(events);
            }
        });
    }

    // Buffers a split reuses from node to node on one thread (see scratchFor).
    struct Scratch {
        std::vector<std::uint32_t> place;       // see partition
        std::vector<std::uint32_t> straddling;  // indices into the node of the primitives in both children
        std::vector<std::array<std::size_t, 3>> chunkStarts;  // sortToSides
        std::vector<SplitBounds> clipped;                     // the straddling primitives' bounds in each child
        SplitEvents sides[2];                                 // distribute: the kept primitives' events per child
        SplitEvents fresh;                                    // mergeEvents: the clipped primitives' events
    };

    // A node below kTaskPrimitives runs no task while it splits, so no other node's split runs
    // on its thread in between: it borrows the thread's buffers, and the many small nodes
    // allocate nothing but their children. A larger node's chunk tasks may run other nodes'
    // splits on its thread, so it uses buffers of its own (`own`).
    static Scratch& scratchFor(std::size_t primitives, Scratch& own) {
        thread_local Scratch shared;
        return primitives < kTaskPrimitives ? shared : own;
    }

    // A pointer to `v`'s first n items, growing it if it is shorter (never shrinking, so a
    // reused buffer is not filled again).
    template <typename Vector>
    static auto* atLeast(Vector& v, std::size_t n) {
        if (v.size() < n) v.resize(n);
        return v.data();
    }

    // Sorts the node's primitives to the two sides. One that straddles the plane is
    // clipped to each child's voxel; one that lies on a single side keeps its bounds
    // and, for the sweep, its already sorted events (Wald and Havran 2006, section 4.3),
    // so that no node sorts more than its straddling primitives' events.
    Partition<KdNode> partition(KdNode& node, const SahSplit& split) const {
        const int axis = split.axis;
        Partition<KdNode> parts{axis, split.pos, {}, {}};
        KdNode& below = parts.below;
        KdNode& above = parts.above;
        below.voxel = above.voxel = node.voxel;
        below.voxel.hi[axis] = above.voxel.lo[axis] = split.pos;
        below.depth = above.depth = node.depth + 1;

        const std::size_t n = node.primitives.size();
        Scratch own;
        Scratch& scratch = scratchFor(n, own);
        const std::array<std::size_t, 3> sides = placeSides(node, split, scratch);
        if (sides[Both] == 0 && (sides[Below] == 0 || sides[Above] == 0) &&
            withinBudget(node.referenceBudget, double(n))) {
            // The plane cuts off empty space: the other child gets the node's primitives, their
            // bounds and their sorted events as they are, so they move there instead of being
            // dealt out and merged (the same child). The tree scene's foliage in its large box
            // makes 13,324 of its 21,739 splits so, with 35 % of the primitives all its splits
            // hold: fewer build instructions, measured in docs/benchmarks.md.
            KdNode& child = sides[Below] == 0 ? above : below;
            child.primitives = std::move(node.primitives);
            child.boxes = std::move(node.boxes);
            child.events = std::move(node.events);
            return parts;
        }
        sortToSides(node, sides, parts, scratch);
        const std::size_t belowKept = below.primitives.size(), aboveKept = above.primitives.size();
        addClipped(node, split, below, above, scratch);
        if (!carriesEvents(settings_, n)) return parts;
        const bool belowCarries = carriesEvents(settings_, below.primitives.size());
        const bool aboveCarries = carriesEvents(settings_, above.primitives.size());
        for (int a = 0; a < 3; ++a) {
            if (!belowCarries && !aboveCarries) break;
            const std::array<std::size_t, 2> kept = distribute(node.events[a], scratch);
            if (belowCarries) mergeEvents(below, belowKept, a, scratch.sides[0].data(), kept[0], scratch.fresh);
            if (aboveCarries) mergeEvents(above, aboveKept, a, scratch.sides[1].data(), kept[1], scratch.fresh);
        }
        return parts;
    }

    static constexpr std::uint32_t kNone = ~0u;
    enum Side : std::uint32_t { Below = 0, Above = 1, Both = 2 };  // Below and Above are isAbove

    // Records in scratch.place the side of the plane each primitive lies on (Both: it straddles
    // the plane), and in scratch.chunkStarts how many of each side each chunk has (see
    // sortToSides); returns how many primitives each side has in all.
    static std::array<std::size_t, 3> placeSides(const KdNode& node, const SahSplit& split, Scratch& scratch) {
        std::uint32_t* const place = atLeast(scratch.place, node.primitives.size());
        const Chunks chunks = nodeChunks(node.primitives.size());
        std::vector<std::array<std::size_t, 3>>& starts = scratch.chunkStarts;  // per chunk and side
        starts.assign(chunks.count(), {0, 0, 0});
        forEachChunk(chunks, [&](std::size_t c, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const FloatBox& box = node.boxes[i];
                const bool b = box.below(split.axis, split.pos, split.planarBelow);
                const bool a = box.above(split.axis, split.pos, split.planarBelow);
                place[i] = b && a ? Both : a ? Above : Below;
                ++starts[c][place[i]];
            }
        });
        std::array<std::size_t, 3> total = {0, 0, 0};
        for (std::array<std::size_t, 3>& chunk : starts)
            for (int side = 0; side < 3; ++side) chunk[side] = std::exchange(total[side], total[side] + chunk[side]);
        return total;
    }

    // Puts each primitive that lies on one side of the plane into that child, in the node's
    // order, and records its place there in scratch.place: (index << 1) | isAbove, or kNone
    // for one that straddles the plane (listed in scratch.straddling, in order). One array,
    // looked up once per event in the events' (random) primitive order: at the top levels it
    // does not fit in the caches. A large node is sorted in chunks on all threads, each
    // chunk's primitives placed after the previous chunk's (placeSides counted them), so the
    // children are the same for any thread count.
    static void sortToSides(const KdNode& node, const std::array<std::size_t, 3>& total, Partition<KdNode>& parts,
                            Scratch& scratch) {
        std::uint32_t* const place = scratch.place.data();
        const Chunks chunks = nodeChunks(node.primitives.size());
        const std::vector<std::array<std::size_t, 3>>& starts = scratch.chunkStarts;
        resize(parts.below, total[Below], total[Both]);
        resize(parts.above, total[Above], total[Both]);
        scratch.straddling.resize(total[Both]);
        forEachChunk(chunks, [&](std::size_t c, std::size_t begin, std::size_t end) {
            std::array<std::size_t, 3> next = starts[c];
            for (std::size_t i = begin; i < end; ++i) {
                const std::uint32_t side = place[i];
                const std::size_t at = next[side]++;
                if (side == Both) {
                    scratch.straddling[at] = std::uint32_t(i);
                    place[i] = kNone;
                    continue;
                }
                KdNode& child = side == Below ? parts.below : parts.above;
                child.primitives[at] = node.primitives[i];
                child.boxes[at] = node.boxes[i];
                place[i] = std::uint32_t(at) << 1 | side;
            }
        });
    }

    // Sizes a child for `kept` primitives, with room for `clipped` more.
    static void resize(KdNode& child, std::size_t kept, std::size_t clipped) {
        child.primitives.reserve(kept + clipped);
        child.boxes.reserve(kept + clipped);
        child.primitives.resize(kept);
        child.boxes.resize(kept);
    }

    // Perfect splits: each straddling primitive's own extent inside each child's voxel, added
    // in order unless it misses the voxel (rounding). Clipped in chunks on all threads in a
    // large node: a clip costs a few hundred nanoseconds.
    void addClipped(const KdNode& node, const SahSplit& split, KdNode& below, KdNode& above, Scratch& scratch) const {
        const std::vector<std::uint32_t>& straddling = scratch.straddling;
        std::vector<SplitBounds>& clipped = scratch.clipped;
        clipped.resize(straddling.size());
        forEachChunk(nodeChunks(straddling.size(), 256, node.primitives.size()),
                     [&](std::size_t, std::size_t begin, std::size_t end) {
                         for (std::size_t i = begin; i < end; ++i) {
                             const std::uint32_t id = node.primitives[straddling[i]];
                             clipped[i] = prims_.visit(id, [&](const auto& p) {
                                 return splitClippedBounds(p, node.voxel, split.axis, split.pos);
                             });
                         }
                     });
        for (std::size_t i = 0; i < straddling.size(); ++i) {
            const std::uint32_t id = node.primitives[straddling[i]];
            if (!clipped[i].below.empty()) add(below, id, toFloatBox(clipped[i].below, below.voxel));
            if (!clipped[i].above.empty()) add(above, id, toFloatBox(clipped[i].above, above.voxel));
        }
    }

    // Deals the node's sorted events on one axis out to scratch.sides, per child, renumbered to
    // the primitives' places there, still sorted; returns how many each side got. A straddling
    // primitive's events are dropped (its clipped bounds make new ones). Without branches (the
    // sides come in random order, and a mispredicted branch per event cost more than the rest):
    // each event is written to both sides, one slot past each side's events, and only its own
    // side's end moves on.
    static std::array<std::size_t, 2> distribute(const SplitEvents& events, Scratch& scratch) {
        SplitEvent* const belowFirst = atLeast(scratch.sides[0], events.size() + 1);
        SplitEvent* const aboveFirst = atLeast(scratch.sides[1], events.size() + 1);
        SplitEvent* below = belowFirst;
        SplitEvent* above = aboveFirst;
        const std::uint32_t* const place = scratch.place.data();
        for (const SplitEvent& e : events) {
            const std::uint32_t p = place[e.primitive()];
            const SplitEvent renumbered(e.pos, p >> 1, e.type());
            *below = renumbered;
            *above = renumbered;
            const std::uint32_t kept = p != kNone, isAbove = p & 1;
            below += kept & (isAbove ^ 1);
            above += kept & isAbove;
        }
        return {std::size_t(below - belowFirst), std::size_t(above - aboveFirst)};
    }

    // A child's events on `axis`: its `keptCount` kept events (sorted, renumbered) merged with
    // the freshly sorted events of its clipped primitives, which are its primitives from
    // `firstClipped` on. Equal events keep the kept ones first, as a stable merge does.
    static void mergeEvents(KdNode& child, std::size_t firstClipped, int axis, const SplitEvent* kept,
                            std::size_t keptCount, SplitEvents& fresh) {
        fresh.clear();
        for (std::size_t i = firstClipped; i < child.primitives.size(); ++i)
            addEvents(child.boxes[i], std::uint32_t(i), axis, fresh);
        std::sort(fresh.begin(), fresh.end());
        SplitEvents& events = child.events[axis];
        events.resize(keptCount + fresh.size());
        mergeSortedEvents(kept, kept + keptCount, fresh.data(), fresh.data() + fresh.size(), events.data());
    }

    // Whether children holding `references` in all fit in their parent's `budget`.
    static bool withinBudget(double budget, double references) { return references > 0 && references <= budget; }

    // Gives each child its share of the parent's budget, or returns false when the children's
    // references alone exceed it (the parent becomes a leaf).
    static bool shareBudget(double budget, KdNode& below, KdNode& above) {
        const double references = double(below.primitives.size() + above.primitives.size());
        if (!withinBudget(budget, references)) return false;
        below.referenceBudget = budget * double(below.primitives.size()) / references;
        above.referenceBudget = budget - below.referenceBudget;
        return true;
    }

    static std::uint32_t add(KdNode& child, std::uint32_t id, const FloatBox& box) {
        child.primitives.push_back(id);
        child.boxes.push_back(box);
        return std::uint32_t(child.primitives.size() - 1);
    }

    const Primitives& prims_;
    const KdSettings& settings_;
    int maxDepth_;
    double rootArea_;
};

// C_I is a triangle's cost, and the SAH uses the mean over the scene's primitives of each
// kind's test cost relative to it.
KdSettings withSceneCosts(const Primitives& prims, const KdSettings& settings) {
    KdSettings s = settings;
    if (prims.size() == 0) return s;
    double weight = 0;
    forEachKind([&]<class K>(std::type_identity<K>) { weight += K::kTestCost * prims.count<K>(); });
    s.intersectionCost *= weight / prims.size();
    return s;
}

KdNode makeRoot(const Primitives& prims) {
    KdNode root;
    root.voxel = roundOutToFloat(prims.bounds());
    const std::uint32_t n = prims.size();
    root.referenceBudget = kReferenceBudgetPerPrimitive * n;
    root.primitives.resize(n);
    root.boxes.resize(n);
#pragma omp parallel for schedule(static) if (n >= kTaskPrimitives)
    for (std::int64_t id = 0; id < std::int64_t(n); ++id) {
        root.primitives[id] = std::uint32_t(id);
        root.boxes[id] = toFloatBox(prims.bounds(std::uint32_t(id)), root.voxel);
    }
    return root;
}

}  // namespace

std::unique_ptr<Accelerator> buildKdTree(const Primitives& prims, const KdSettings& userSettings,
                                         TriangleTest triangles) {
    const Stopwatch stopwatch;
    const KdSettings settings = withSceneCosts(prims, userSettings);
    KdNode root = makeRoot(prims);
    const Aabb bounds = root.voxel;
    FlatTree flat = buildFlatTree(std::move(root), KdSplitter(prims, settings));
    auto tree = std::make_unique<SplitTree>(prims, bounds, std::move(flat),
                                            std::string("kd-") + kdSplitMethodName(settings.splitMethod),
                                            sahCosts(settings), triangles);
    tree->setBuildTime(stopwatch.seconds(), buildThreads(prims.size()));
    return tree;
}

}  // namespace rt
