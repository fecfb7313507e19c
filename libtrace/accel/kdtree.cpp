#include "accel/kdtree.h"

#include <algorithm>
#include <array>
#include <cmath>

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

    static void sortEvents(KdNode& node) {
        for (int axis = 0; axis < 3; ++axis) {
            std::vector<SplitEvent>& events = node.events[axis];
            events.reserve(2 * node.boxes.size());
            addEventsByType(node.boxes, axis, events);  // spares radixSortEvents its type pass
            radixSortEvents(events);
        }
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

        constexpr std::uint32_t kNone = ~0u;
        const std::size_t n = node.primitives.size();
        for (KdNode* child : {&below, &above}) {
            child->primitives.reserve(n);
            child->boxes.reserve(n);
        }
        // Each primitive's place in its one child, (index << 1) | isAbove, or kNone if it
        // straddles. One array, looked up once per event in the events' (random) primitive
        // order: at the top levels it does not fit in the caches.
        std::vector<std::uint32_t> place(n, kNone);
        std::vector<std::uint32_t> straddling;
        for (std::uint32_t i = 0; i < n; ++i) {
            const FloatBox& box = node.boxes[i];
            const bool b = box.below(axis, split.pos, split.planarBelow);
            const bool a = box.above(axis, split.pos, split.planarBelow);
            if (b && a) {
                straddling.push_back(i);
            } else if (b) {
                place[i] = add(below, node.primitives[i], box) << 1;
            } else {
                place[i] = add(above, node.primitives[i], box) << 1 | 1;
            }
        }
        const std::size_t belowKept = below.primitives.size(), aboveKept = above.primitives.size();
        for (std::uint32_t i : straddling) {
            addClipped(below, node.primitives[i]);
            addClipped(above, node.primitives[i]);
        }
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

    // Perfect split: the primitive's own extent inside the child's voxel.
    void addClipped(KdNode& child, std::uint32_t id) const {
        const Aabb clipped = prims_.visit(id, [&](const auto& p) { return clippedBounds(p, child.voxel); });
        if (!clipped.empty()) add(child, id, toFloatBox(clipped, child.voxel));
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
    tree->setBuildSeconds(stopwatch.seconds());
    return tree;
}

}  // namespace rt
