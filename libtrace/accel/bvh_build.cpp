// The BVH's build: top-down, each node's children found by splitting its primitives in two by the
// binned surface area heuristic (Wald 2007: kBins bins of the primitives' centres per axis) and
// then splitting the child of the largest surface area again, as Embree's wide builders do, until
// the node has eight children or none is worth splitting. Subtrees of kTaskPrimitives or more are
// built as OpenMP tasks, and the passes over a node of that many (its bounds, its bins, its
// partition) run in chunks on all threads (build_chunks.h), so that the top levels, where one node
// holds most of the scene, do not leave the other threads waiting. Every choice depends on the
// primitives alone, never on the threads, so the BVH is the same for any number of them.
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "accel/build_chunks.h"
#include "accel/bvh.h"
#include "accel/bvh_tree.h"
#include "core/parallel_errors.h"
#include "core/simd.h"
#include "core/stopwatch.h"

namespace rt {

namespace {

constexpr int kBins = 16;
// Below this depth (in wide nodes) the binned SAH splits; from it on, the object median of the
// longest axis, which halves a node at each level and so bounds the depth by kMaxBvhDepth.
constexpr int kMedianDepth = kMaxBvhDepth - 40;

// A box in float, as the build bins and partitions boxes: half the bytes of one in double, and
// each corner four lanes (the fourth unused) that the compiler grows with one min or max
// instruction, as Embree's builders keep their boxes. A primitive's box is rounded outward (see
// makeRefs), so a node's box, the union of its references', still holds its primitives; it is at
// most a float's rounding larger than the exact one, which costs the traversal nothing measurable.
struct BuildBox {
    alignas(16) float lo[4] = {kFloatInf, kFloatInf, kFloatInf, kFloatInf};
    alignas(16) float hi[4] = {-kFloatInf, -kFloatInf, -kFloatInf, -kFloatInf};

    static constexpr float kFloatInf = std::numeric_limits<float>::infinity();

    void extend(const BuildBox& b) {
#if RT_SIMD_SSE2
        _mm_store_ps(lo, _mm_min_ps(_mm_load_ps(lo), _mm_load_ps(b.lo)));
        _mm_store_ps(hi, _mm_max_ps(_mm_load_ps(hi), _mm_load_ps(b.hi)));
#else
        for (int k = 0; k < 4; ++k) {
            lo[k] = std::min(lo[k], b.lo[k]);
            hi[k] = std::max(hi[k], b.hi[k]);
        }
#endif
    }
    bool empty() const { return lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]; }
    float surfaceArea() const {
        if (empty()) return 0;
        const float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
        return 2 * (dx * dy + dy * dz + dz * dx);
    }
    int longestAxis() const {
        const float dx = hi[0] - lo[0], dy = hi[1] - lo[1], dz = hi[2] - lo[2];
        return dx >= dy && dx >= dz ? 0 : (dy >= dz ? 1 : 2);
    }
    Aabb aabb() const { return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
};

// The float nearest x on the side of -inf (down) or +inf (up): a box rounded outward.
float roundDown(Real x) {
    const auto f = float(x);
    return Real(f) > x ? std::nextafter(f, -BuildBox::kFloatInf) : f;
}
float roundUp(Real x) {
    const auto f = float(x);
    return Real(f) < x ? std::nextafter(f, BuildBox::kFloatInf) : f;
}

// A primitive as the build sees it: its box, the box's centre (lane 3 holds nothing) and its index
// in the Primitives. 48 bytes.
struct PrimRef {
    BuildBox box;
    float centre[3];
    std::uint32_t id;
};

// What a leaf of `n` primitives costs to test in the SAH: its pairs of blocks of kSimdWidth, which
// the AVX2 and AVX-512 traversals test in one register (accel/leaf_tests.h), as Embree prices its
// Triangle4 leaves by blocks. Counted by primitives, the SAH made leaves of one primitive (1.07 on
// average, 20,000 scattered triangles): 40 % more nodes than leaves, and half-empty blocks.
double blocks(std::uint32_t n) { return double((n + 2 * kSimdWidth - 1) / (2 * kSimdWidth)); }

// The bounds of some references and the bounds of their centres.
struct Extent {
    BuildBox bounds, centres;

    void add(const PrimRef& ref) {
        bounds.extend(ref.box);
        for (int a = 0; a < 3; ++a) {
            centres.lo[a] = std::min(centres.lo[a], ref.centre[a]);
            centres.hi[a] = std::max(centres.hi[a], ref.centre[a]);
        }
    }
    void merge(const Extent& o) {
        bounds.extend(o.bounds);
        centres.extend(o.centres);
    }
};

// The references [begin, end) of the build's array, their bounds and the bounds of their centres.
struct Range {
    std::uint32_t begin = 0, end = 0;
    BuildBox bounds, centres;
    std::uint32_t size() const { return end - begin; }
};

// The references of a range counted and bounded per bin of each axis, as the SAH sweep needs them.
struct Bins {
    std::uint32_t counts[3][kBins] = {};
    BuildBox boxes[3][kBins];

    void merge(const Bins& o) {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < kBins; ++b) {
                counts[a][b] += o.counts[a][b];
                boxes[a][b].extend(o.boxes[a][b]);
            }
    }
};

// body(first, last, result) over [begin, end) in the chunks of build_chunks.h (several, on all
// threads, for kTaskPrimitives references or more; else one), the chunks' results merged into `all`
// (empty to begin with) in chunk order. Bounds and counts merge exactly in any order, so the result
// is the same for any thread count. `all` is the caller's, not returned: the bins of a small node
// cost more to copy than to fill.
template <class Result, class Body>
void reduceInChunks(std::uint32_t begin, std::uint32_t end, Result& all, const Body& body) {
    const Chunks chunks = nodeChunks(end - begin);
    if (chunks.count() == 1) return body(begin, end, all);
    std::vector<Result> parts(chunks.count());
    forEachChunk(chunks, [&](std::size_t c, std::size_t first, std::size_t last) {
        body(begin + std::uint32_t(first), begin + std::uint32_t(last), parts[c]);
    });
    for (const Result& part : parts) all.merge(part);
}

// How a range is split in two: at a bin boundary of an axis, at the median of an axis (deep
// nodes), or, when all its centres coincide, into its first and second half as they lie.
struct Split {
    enum Kind { Binned, Median, Halves } kind = Halves;
    int axis = 0;
    int bin = 0;  // Binned: the bins below it go to the first part
};

struct BuildNode {
    Range range;
    std::vector<std::unique_ptr<BuildNode>> children;  // none for a leaf
};

class BvhBuilder {
public:
    BvhBuilder(const Primitives& prims, const BvhSettings& settings) : settings_(settings) { makeRefs(prims); }

    // The whole hierarchy, on the threads OpenMP has (one for a small scene).
    BuildNode build() {
        BuildNode root;
        if (refs_.empty()) return root;
        const Range all = rangeOf(0, std::uint32_t(refs_.size()));
        ParallelErrors errors;
        const int threads = threadsFor(refs_.size());
#pragma omp parallel num_threads(threads) if (threads > 1)
#pragma omp single
        errors.capture([&] { buildNode(all, split(all, 0), 0, root, errors); });
        errors.rethrowIfAny();
        return root;
    }

    static int threadsFor(std::size_t refs) { return refs >= kTaskPrimitives ? omp_get_max_threads() : 1; }
    std::uint32_t id(std::uint32_t ref) const { return refs_[ref].id; }

private:
    // One reference per primitive, its box padded (see padding()).
    void makeRefs(const Primitives& prims) {
        const std::uint32_t n = prims.size();
        refs_.resize(n);
        const Real pad = padding(prims.bounds());
#pragma omp parallel for schedule(static) if (n >= kTaskPrimitives)
        for (std::int64_t i = 0; i < std::int64_t(n); ++i) {
            const Aabb box = prims.bounds(std::uint32_t(i));
            PrimRef& ref = refs_[std::size_t(i)];
            for (int a = 0; a < 3; ++a) {
                ref.box.lo[a] = roundDown(box.lo[a] - pad);
                ref.box.hi[a] = roundUp(box.hi[a] + pad);
                ref.centre[a] = (ref.box.lo[a] + ref.box.hi[a]) * 0.5f;
            }
            ref.id = std::uint32_t(i);
        }
    }

    // The distance every box is widened by: a primitive's hit is rounded, and may lie outside its
    // exact bounds by some units in the last place of the scene's coordinates, farther along a ray
    // that grazes a flat box; the traversal must still enter its box there (the property tests
    // shoot rays along axes and from surfaces). A few ulps of the scene's largest coordinate.
    static Real padding(const Aabb& scene) {
        const Real largest = largestMagnitude(scene);
        return std::isfinite(largest) ? 16 * std::numeric_limits<Real>::epsilon() * largest : 0;
    }

    Range rangeOf(std::uint32_t begin, std::uint32_t end) const {
        Extent e;
        reduceInChunks(begin, end, e, [this](std::uint32_t first, std::uint32_t last, Extent& out) {
            for (std::uint32_t i = first; i < last; ++i) out.add(refs_[i]);
        });
        return {begin, end, e.bounds, e.centres};
    }

    // The bins of a range: kBins over its centres' extent along each axis. The binning and the
    // partition both place references through binOf, so that they agree on every one.
    struct Binning {
        float lo[3];
        float scale[3];  // bins per unit; 0 along an axis the centres do not spread over

        explicit Binning(const Range& r) {
            for (int a = 0; a < 3; ++a) {
                lo[a] = r.centres.lo[a];
                const float extent = r.centres.hi[a] - r.centres.lo[a];
                scale[a] = extent > 0 ? float(kBins) / extent : 0;
            }
        }
        int binOf(int axis, const PrimRef& ref) const {
            return std::clamp(int((ref.centre[axis] - lo[axis]) * scale[axis]), 0, kBins - 1);
        }
    };

    // The split of `r`, or nullopt where a leaf costs less by the SAH (or it holds one primitive).
    std::optional<Split> split(const Range& r, int depth) const {
        const std::uint32_t n = r.size();
        if (n <= 1) return std::nullopt;
        const int axis = r.centres.longestAxis();
        if (r.centres.hi[axis] == r.centres.lo[axis]) {  // all centres coincide: no plane parts them
            if (n <= std::uint32_t(settings_.maxLeafPrimitives)) return std::nullopt;
            return Split{Split::Halves, 0, 0};
        }
        if (depth >= kMedianDepth) return Split{Split::Median, axis, 0};
        double bestCost = std::numeric_limits<double>::infinity();
        Split best;
        Bins bins;
        binsOf(r, bins);
        for (int a = 0; a < 3; ++a) {
            if (!(r.centres.hi[a] > r.centres.lo[a])) continue;
            const auto [cost, bin] = bestBinOf(bins, a, n);
            if (cost < bestCost) {
                bestCost = cost;
                best = {Split::Binned, a, bin};
            }
        }
        const double area = r.bounds.surfaceArea();
        const double splitCost =
            settings_.traversalCost + settings_.intersectionCost * (area > 0 ? bestCost / area : blocks(n));
        const double leafCost = settings_.intersectionCost * blocks(n);
        if (n <= std::uint32_t(settings_.maxLeafPrimitives) && leafCost <= splitCost) return std::nullopt;
        return best;
    }

    // Fills the (empty) bins of `r` along each axis its centres spread over, in one pass over its references.
    void binsOf(const Range& r, Bins& bins) const {
        const Binning binning(r);
        reduceInChunks(r.begin, r.end, bins, [&](std::uint32_t first, std::uint32_t last, Bins& out) {
            for (std::uint32_t i = first; i < last; ++i)
                for (int a = 0; a < 3; ++a) {
                    if (binning.scale[a] == 0) continue;
                    const int bin = binning.binOf(a, refs_[i]);
                    ++out.counts[a][bin];
                    out.boxes[a][bin].extend(refs_[i].box);
                }
        });
    }

    // The bin boundary of `axis` with the least area-weighted blocks (the SAH's sum, unscaled), for a
    // range of n references.
    // An empty bin changes neither side, so the boundary after it splits as the one before it does
    // and cannot cost less: both sweeps skip empty bins (in a small node, most are).
    static std::pair<double, int> bestBinOf(const Bins& bins, int axis, std::uint32_t n) {
        const std::uint32_t* counts = bins.counts[axis];
        const BuildBox* boxes = bins.boxes[axis];
        double aboveCost[kBins];  // aboveCost[b]: bins b.. together
        BuildBox above;
        std::uint32_t aboveCount = 0;
        double cost = 0;
        for (int b = kBins - 1; b > 0; --b) {
            if (counts[b] != 0) {
                above.extend(boxes[b]);
                aboveCount += counts[b];
                cost = double(above.surfaceArea()) * blocks(aboveCount);
            }
            aboveCost[b] = cost;
        }
        std::pair<double, int> best{std::numeric_limits<double>::infinity(), 1};
        BuildBox below;
        std::uint32_t belowCount = 0;
        for (int b = 1; b < kBins; ++b) {
            if (counts[b - 1] == 0) continue;
            below.extend(boxes[b - 1]);
            belowCount += counts[b - 1];
            if (belowCount == n) break;
            cost = double(below.surfaceArea()) * blocks(belowCount) + aboveCost[b];
            if (cost < best.first) best = {cost, b};
        }
        return best;
    }

    // Reorders the references of `r` into its two parts.
    std::pair<Range, Range> partition(const Range& r, const Split& s) {
        const auto first = refs_.begin() + r.begin, last = refs_.begin() + r.end;
        std::uint32_t middle = r.begin + r.size() / 2;
        if (s.kind == Split::Binned) {
            const Binning binning(r);
            const auto below = [&](const PrimRef& ref) { return binning.binOf(s.axis, ref) < s.bin; };
            middle = nodeChunks(r.size()).count() == 1
                         ? std::uint32_t(std::partition(first, last, below) - refs_.begin())
                         : partitionInChunks(r, below);
        } else if (s.kind == Split::Median) {
            const auto before = [&](const PrimRef& a, const PrimRef& b) {
                const float ca = a.centre[s.axis], cb = b.centre[s.axis];
                return ca < cb || (ca == cb && a.id < b.id);  // a total order: the same halves every time
            };
            std::nth_element(first, refs_.begin() + middle, last, before);
        }
        return {rangeOf(r.begin, middle), rangeOf(middle, r.end)};
    }

    // A stable partition of a large range on all threads: each chunk counts its references below the
    // split, then copies them, in order, to their places in a second array, which is copied back.
    // Returns where the second part begins.
    template <class Below>
    std::uint32_t partitionInChunks(const Range& r, const Below& below) {
        const Chunks chunks = nodeChunks(r.size());
        std::vector<std::uint32_t> belowIn(chunks.count());
        forEachChunk(chunks, [&](std::size_t c, std::size_t first, std::size_t last) {
            belowIn[c] =
                std::uint32_t(std::count_if(refs_.begin() + r.begin + first, refs_.begin() + r.begin + last, below));
        });
        std::vector<std::uint32_t> belowBefore(chunks.count());  // in the chunks before each chunk
        std::uint32_t belowAll = 0;
        for (std::size_t c = 0; c < chunks.count(); ++c) {
            belowBefore[c] = belowAll;
            belowAll += belowIn[c];
        }
        std::vector<PrimRef> sorted(r.size());
        forEachChunk(chunks, [&](std::size_t c, std::size_t first, std::size_t last) {
            std::size_t nextBelow = belowBefore[c], nextAbove = belowAll + (first - belowBefore[c]);
            for (std::size_t i = first; i < last; ++i) {
                const PrimRef& ref = refs_[r.begin + i];
                sorted[below(ref) ? nextBelow++ : nextAbove++] = ref;
            }
        });
        forEachChunk(chunks, [&](std::size_t, std::size_t first, std::size_t last) {
            std::copy(sorted.begin() + first, sorted.begin() + last, refs_.begin() + r.begin + first);
        });
        return r.begin + belowAll;
    }

    // The node of `r` (split by `s`): up to eight children, each a leaf or a node built the same way.
    void buildNode(const Range& r, const std::optional<Split>& s, int depth, BuildNode& out, ParallelErrors& errors) {
        out.range = r;
        if (!s || errors.failed()) return;
        std::vector<Range> parts{r};
        std::vector<std::optional<Split>> splits{s};
        while (parts.size() < std::size_t(kBvhWidth)) {
            // Open the part of the largest area still worth splitting (the first of equals).
            int widest = -1;
            for (int k = 0; k < int(parts.size()); ++k)
                if (splits[k] && (widest < 0 || parts[k].bounds.surfaceArea() > parts[widest].bounds.surfaceArea()))
                    widest = k;
            if (widest < 0) break;
            auto [below, above] = partition(parts[widest], *splits[widest]);
            parts[widest] = below;
            splits[widest] = split(below, depth + 1);
            parts.insert(parts.begin() + widest + 1, above);
            splits.insert(splits.begin() + widest + 1, split(above, depth + 1));
        }
        out.children.resize(parts.size());
        for (std::size_t k = 0; k < parts.size(); ++k) {
            out.children[k] = std::make_unique<BuildNode>();
            BuildNode* child = out.children[k].get();
            if (parts[k].size() < kTaskPrimitives || !splits[k]) {
                buildNode(parts[k], splits[k], depth + 1, *child, errors);
                continue;
            }
            // The task reaches what it needs through pointers to what outlives the parallel region.
            BvhBuilder* self = this;
            ParallelErrors* failures = &errors;
            const Range part = parts[k];
            const Split partSplit = *splits[k];
#pragma omp task default(none) firstprivate(self, failures, part, partSplit, depth, child)
            failures->capture([&] { self->buildNode(part, partSplit, depth + 1, *child, *failures); });
        }
    }

    const BvhSettings& settings_;
    std::vector<PrimRef> refs_;
};

// Lays the build's nodes out in pre-order: each node's boxes and children, and each leaf's place
// in the LeafStore (written afterwards, on all threads).
class Flattener {
public:
    // ids: the primitive of each of the build's references, in the order the build left them.
    Flattener(const Primitives& prims, std::vector<std::uint32_t> ids) : prims_(prims), ids_(std::move(ids)) {}

    void flatten(const BuildNode& root) {
        if (root.range.size() == 0) return;
        // Arrays of the final size: grown by doubling, the nodes (448 bytes each in double) were
        // copied twice over on average, a third of the flattening of balls2's 150,000 nodes.
        std::size_t inner = 0, leaves = 0;
        count(root, inner, leaves);
        nodes_.reserve(std::max<std::size_t>(inner, 1));
        leaves_.reserve(leaves);
        if (root.children.empty()) {  // one leaf: a root of one child
            nodes_.emplace_back();
            addChild(0, root);
            return;
        }
        addNode(root);
    }

    std::vector<BvhNode> takeNodes() { return std::move(nodes_); }

    static void count(const BuildNode& b, std::size_t& inner, std::size_t& leaves) {
        if (b.children.empty()) {
            ++leaves;
            return;
        }
        ++inner;
        for (const auto& child : b.children) count(*child, inner, leaves);
    }

    LeafStore writeLeaves(TriangleTest triangles) const {
        LeafStore store(triangles);
        store.resize(units_);
        const auto count = std::int64_t(leaves_.size());
#pragma omp parallel for schedule(dynamic, 1024) if (count >= std::int64_t(kTaskPrimitives))
        for (std::int64_t k = 0; k < count; ++k) {
            const Leaf& leaf = leaves_[std::size_t(k)];
            store.write(prims_, &ids_[leaf.range.begin], leaf.sizes, leaf.unit);
        }
        return store;
    }

private:
    std::uint32_t addNode(const BuildNode& b) {
        const auto index = std::uint32_t(nodes_.size());
        nodes_.emplace_back();
        for (const auto& child : b.children) addChild(index, *child);
        return index;
    }

    void addChild(std::uint32_t parent, const BuildNode& child) {
        if (!child.children.empty()) {
            const std::uint32_t index = addNode(child);
            nodes_[parent].add(child.range.bounds.aabb(), BvhChild::inner(index));
            return;
        }
        const LeafPrimitives sizes = LeafStore::sizesOf(prims_, &ids_[child.range.begin], child.range.size());
        if (units_ + sizes.units() >= (std::size_t(1) << 31)) throw std::length_error("BVH leaves beyond 32 GB");
        leaves_.push_back({child.range, sizes, units_});
        nodes_[parent].add(child.range.bounds.aabb(), BvhChild::leaf(std::uint32_t(units_)));
        units_ += sizes.units();
    }

    struct Leaf {
        Range range;
        LeafPrimitives sizes;
        std::size_t unit;
    };
    const Primitives& prims_;
    std::vector<std::uint32_t> ids_;
    std::vector<BvhNode> nodes_;
    std::vector<Leaf> leaves_;
    std::size_t units_ = 0;
};

}  // namespace

std::unique_ptr<Accelerator> buildBvh(const Primitives& prims, const BvhSettings& settings, TriangleTest triangles) {
    const Stopwatch stopwatch;
    BvhBuilder builder(prims, settings);
    const BuildNode root = builder.build();
    std::vector<std::uint32_t> ids(prims.size());
    for (std::uint32_t i = 0; i < prims.size(); ++i) ids[i] = builder.id(i);
    Flattener flat(prims, std::move(ids));
    flat.flatten(root);
    LeafStore leaves = flat.writeLeaves(triangles);
    return std::make_unique<Bvh>(prims, flat.takeNodes(), std::move(leaves), settings, stopwatch.seconds(),
                                 BvhBuilder::threadsFor(prims.size()));
}

}  // namespace rt
