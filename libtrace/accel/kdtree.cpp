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
    std::vector<std::uint32_t> primitives;          // ids into Primitives
    std::vector<FloatBox> boxes;                    // their bounds clipped to the voxel
    std::array<std::vector<SplitEvent>, 3> events;  // Sweep only: per axis, sorted, indices into `primitives`
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
                std::vector<SplitEvent>& events = node.events[axis];
                events.reserve(2 * node.boxes.size());
                addEventsByType(node.boxes, int(axis), events);  // spares radixSortEvents its type pass
                radixSortEvents(events);
            }
        });
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

        // Each primitive's place in its one child, (index << 1) | isAbove, or kNone if it
        // straddles. One array, looked up once per event in the events' (random) primitive
        // order: at the top levels it does not fit in the caches.
        const std::size_t n = node.primitives.size();
        std::vector<std::uint32_t> place(n, kNone);
        const std::vector<std::uint32_t> straddling = sortToSides(node, split, parts, place);
        const std::size_t belowKept = below.primitives.size(), aboveKept = above.primitives.size();
        addClipped(node, straddling, below, above);
        if (carriesEvents(settings_, n)) {
            for (int a = 0; a < 3; ++a) {
                std::vector<SplitEvent>& belowEvents = below.events[a];
                std::vector<SplitEvent>& aboveEvents = above.events[a];
                belowEvents.reserve(2 * below.primitives.size());
                aboveEvents.reserve(2 * above.primitives.size());
                for (const SplitEvent& e : node.events[a]) {
                    const std::uint32_t p = place[e.primitive()];
                    if (p == kNone) continue;
                    (p & 1 ? aboveEvents : belowEvents).emplace_back(e.pos, p >> 1, e.type());
                }
                mergeClippedEvents(below, belowKept, a);
                mergeClippedEvents(above, aboveKept, a);
            }
            for (KdNode* child : {&below, &above}) {
                if (carriesEvents(settings_, child->primitives.size())) continue;
                for (std::vector<SplitEvent>& events : child->events) events = {};
            }
        }
        return parts;
    }

    static constexpr std::uint32_t kNone = ~0u;

    // Puts each primitive that lies on one side of the plane into that child, in the node's
    // order, and records its place there (see partition); returns the straddling ones, in
    // order. A large node is sorted in chunks on all threads and gathered in chunk order, so
    // the children are the same for any thread count.
    static std::vector<std::uint32_t> sortToSides(const KdNode& node, const SahSplit& split, Partition<KdNode>& parts,
                                                  std::vector<std::uint32_t>& place) {
        struct Sides {
            std::vector<std::uint32_t> below, above, straddling;  // indices into the node
        };
        const Chunks chunks = nodeChunks(node.primitives.size());
        std::vector<Sides> sides(chunks.count());
        forEachChunk(chunks, [&](std::size_t c, std::size_t begin, std::size_t end) {
            for (std::size_t i = begin; i < end; ++i) {
                const FloatBox& box = node.boxes[i];
                const bool b = box.below(split.axis, split.pos, split.planarBelow);
                const bool a = box.above(split.axis, split.pos, split.planarBelow);
                (b && a ? sides[c].straddling : b ? sides[c].below : sides[c].above).push_back(std::uint32_t(i));
            }
        });
        std::vector<std::uint32_t> straddling;
        std::vector<std::size_t> belowAt, aboveAt;  // where each chunk's primitives start in the children
        std::size_t belowCount = 0, aboveCount = 0;
        for (const Sides& chunk : sides) {
            belowAt.push_back(std::exchange(belowCount, belowCount + chunk.below.size()));
            aboveAt.push_back(std::exchange(aboveCount, aboveCount + chunk.above.size()));
            straddling.insert(straddling.end(), chunk.straddling.begin(), chunk.straddling.end());
        }
        resize(parts.below, belowCount, straddling.size());
        resize(parts.above, aboveCount, straddling.size());
        forEachChunk(chunks, [&](std::size_t c, std::size_t, std::size_t) {
            copyTo(node, sides[c].below, parts.below, belowAt[c], 0, place);
            copyTo(node, sides[c].above, parts.above, aboveAt[c], 1, place);
        });
        return straddling;
    }

    // Sizes a child for `kept` primitives, with room for `clipped` more.
    static void resize(KdNode& child, std::size_t kept, std::size_t clipped) {
        child.primitives.reserve(kept + clipped);
        child.boxes.reserve(kept + clipped);
        child.primitives.resize(kept);
        child.boxes.resize(kept);
    }

    // Copies the node's primitives `indices` to the child from `at` on, recording their places.
    static void copyTo(const KdNode& node, const std::vector<std::uint32_t>& indices, KdNode& child, std::size_t at,
                       std::uint32_t isAbove, std::vector<std::uint32_t>& place) {
        for (const std::uint32_t i : indices) {
            child.primitives[at] = node.primitives[i];
            child.boxes[at] = node.boxes[i];
            place[i] = std::uint32_t(at) << 1 | isAbove;
            ++at;
        }
    }

    // Perfect splits: each straddling primitive's own extent inside each child's voxel, added
    // in order unless it misses the voxel (rounding). Clipped in chunks on all threads in a
    // large node: a clip costs a few hundred nanoseconds.
    void addClipped(const KdNode& node, const std::vector<std::uint32_t>& straddling, KdNode& below,
                    KdNode& above) const {
        struct Clipped {
            Aabb below, above;
        };
        std::vector<Clipped> clipped(straddling.size());
        forEachChunk(nodeChunks(straddling.size(), 256, node.primitives.size()),
                     [&](std::size_t, std::size_t begin, std::size_t end) {
                         for (std::size_t i = begin; i < end; ++i) {
                             const std::uint32_t id = node.primitives[straddling[i]];
                             clipped[i] = {clipTo(id, below.voxel), clipTo(id, above.voxel)};
                         }
                     });
        for (std::size_t i = 0; i < straddling.size(); ++i) {
            const std::uint32_t id = node.primitives[straddling[i]];
            if (!clipped[i].below.empty()) add(below, id, toFloatBox(clipped[i].below, below.voxel));
            if (!clipped[i].above.empty()) add(above, id, toFloatBox(clipped[i].above, above.voxel));
        }
    }

    Aabb clipTo(std::uint32_t id, const Aabb& voxel) const {
        return prims_.visit(id, [&](const auto& p) { return clippedBounds(p, voxel); });
    }

    // Gives each child its share of the parent's budget, or returns false when the children's
    // references alone exceed it (the parent becomes a leaf).
    static bool shareBudget(double budget, KdNode& below, KdNode& above) {
        const double references = double(below.primitives.size() + above.primitives.size());
        if (references == 0 || references > budget) return false;
        below.referenceBudget = budget * double(below.primitives.size()) / references;
        above.referenceBudget = budget - below.referenceBudget;
        return true;
    }

    static std::uint32_t add(KdNode& child, std::uint32_t id, const FloatBox& box) {
        child.primitives.push_back(id);
        child.boxes.push_back(box);
        return std::uint32_t(child.primitives.size() - 1);
    }

    // A child's events on `axis` are the parent's events of the primitives that went to
    // this side only (still sorted, renumbered), merged with the freshly sorted events of
    // the clipped primitives, which are the child's primitives from `kept` on.
    static void mergeClippedEvents(KdNode& child, std::size_t kept, int axis) {
        std::vector<SplitEvent>& events = child.events[axis];
        const std::size_t inherited = events.size();
        for (std::size_t i = kept; i < child.primitives.size(); ++i)
            addEvents(child.boxes[i], std::uint32_t(i), axis, events);
        std::sort(events.begin() + std::ptrdiff_t(inherited), events.end());
        std::inplace_merge(events.begin(), events.begin() + std::ptrdiff_t(inherited), events.end());
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

std::unique_ptr<Accelerator> buildKdTree(const Primitives& prims, const KdSettings& userSettings) {
    const Stopwatch stopwatch;
    const KdSettings settings = withSceneCosts(prims, userSettings);
    KdNode root = makeRoot(prims);
    const Aabb bounds = root.voxel;
    FlatTree flat = buildFlatTree(std::move(root), KdSplitter(prims, settings));
    auto tree =
        std::make_unique<SplitTree>(prims, bounds, std::move(flat),
                                    std::string("kd-") + kdSplitMethodName(settings.splitMethod), sahCosts(settings));
    tree->setBuildTime(stopwatch.seconds(), buildThreads(prims.size()));
    return tree;
}

}  // namespace rt
