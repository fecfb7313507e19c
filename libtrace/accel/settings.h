// Every tunable of the accelerators, with its default, in one place (as Embree's
// builder settings). rt-render and rt-inspect expose them on their command lines (--bsp-*, --kd-*), all
// but the binning's two (binningMinimum, bins), which are tuned for the build's speed and kept
// internal; they move the SAH cost a little (docs/benchmarks.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "core/names.h"

namespace rt {

enum class AccelKind { Naive, Bsp, Kd, Bvh };

inline constexpr NamedValues<AccelKind, 4> kAccelKindNames{
    {{"naive", AccelKind::Naive}, {"bsp", AccelKind::Bsp}, {"kd", AccelKind::Kd}, {"bvh", AccelKind::Bvh}}};

// The deepest a tree may be: the traversal's stack holds one entry per level.
inline constexpr int kMaxTreeDepth = 64;
// The ranges the tools accept for the tunables below.
inline constexpr int kMaxLeafPrimitives = 1 << 20;  // BspSettings::minPrimitives
inline constexpr int kMaxKdSamples = 1024;          // KdSettings::samples

struct BspSettings {
    int maxDepth = 20;        // stop subdividing below this depth (thesis 2.4.1)
    int minPrimitives = 4;    // a node with at most this many primitives becomes a leaf
    bool roundRobin = false;  // split axis X, Y, Z, X, ... instead of the longest axis
};

enum class KdSplitMethod {
    Sweep,   // O(N log N) event sweep of Wald and Havran 2006 (thesis [12]); the default
    Sort,    // the thesis's sort per node, O(N log^2 N) (thesis 2.5.1)
    Sample,  // the thesis's sampling of a fixed number of candidate planes per axis
};

inline constexpr NamedValues<KdSplitMethod, 3> kKdSplitMethodNames{
    {{"sweep", KdSplitMethod::Sweep}, {"sort", KdSplitMethod::Sort}, {"sample", KdSplitMethod::Sample}}};

struct KdSettings {
    double traversalCost = 2.0;     // C_T of the SAH (thesis 2.5.1); measured, see docs/trees.md
    double intersectionCost = 0.6;  // C_I of the SAH, for a triangle; a sphere test costs as much
    double emptyBonus = 0.8;        // cost factor for splits that cut off empty space (1 = none)
    std::optional<int> maxDepth;    // default 8 + 1.3 log2(N)
    KdSplitMethod splitMethod = KdSplitMethod::Sweep;
    int samples = 16;  // candidate planes per axis for Sample (8-32 in the thesis)
    // Sweep: nodes of at least this many primitives take the best of `bins` planes per axis
    // (min-max binning, Shevtsov et al. 2007) instead of sweeping sorted events. Linear in the
    // node's primitives, for the top levels, whose event lists do not fit in the caches; the
    // nodes below keep the exact sweep. Measured in docs/benchmarks.md (SAH cost and build time).
    std::size_t binningMinimum = 4096;
    int bins =
        32;  // evenly spaced over the extent of the node's primitives, both ends included (64: a higher SAH cost)
    // A split must lower the tree's SAH cost per ray by at least this much: its own gain over a
    // leaf times the chance that a ray entering the root enters the node (their areas' ratio).
    // Deep in clustered geometry (the tree scene's foliage) the SAH finds split after split that
    // gains almost nothing: build time and memory, no ray time. 0 turns it off (docs/trees.md;
    // 3e-7 measured against 3e-8 and 1e-6 in docs/benchmarks.md).
    double minimumGain = 3e-7;
};

// The wide BVH (accel/bvh.h, docs/trees.md). Its SAH weighs a node's box tests against a leaf's
// block tests: one visit of an eight-wide node (eight slab tests in one or two registers) costs
// about as much as testing one block of kSimdWidth triangles (geometry/triangle_block.h).
struct BvhSettings {
    int maxLeafPrimitives = 8;      // a larger node is always split
    double traversalCost = 1.0;     // C_T: visiting one node
    double intersectionCost = 1.0;  // C_I: testing one block of a leaf
};

// The ray-triangle test of every structure's queries (docs/trees.md, "Watertight triangles").
enum class TriangleTest {
    MollerTrumbore,  // thesis [5]: the fastest; a ray through a shared edge or vertex may slip between its triangles
    Watertight,      // Woop, Benthin and Wald 2013 (geometry/watertight_triangle.h): no ray slips through a closed mesh
};

struct AccelSettings {
    AccelKind kind = AccelKind::Kd;
    TriangleTest triangles = TriangleTest::MollerTrumbore;
    BspSettings bsp;
    KdSettings kd;
    BvhSettings bvh;
};

// By the tables above: "naive", "bsp", "kd", "bvh" and "sweep", "sort", "sample"; nullopt if unknown.
inline std::optional<AccelKind> parseAccelKind(const std::string& name) { return parseNamed(kAccelKindNames, name); }
inline const char* accelKindName(AccelKind kind) { return nameOf(kAccelKindNames, kind); }
inline std::optional<KdSplitMethod> parseKdSplitMethod(const std::string& name) {
    return parseNamed(kKdSplitMethodNames, name);
}
inline const char* kdSplitMethodName(KdSplitMethod method) { return nameOf(kKdSplitMethodNames, method); }

}  // namespace rt
