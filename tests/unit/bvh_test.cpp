// The wide BVH (issue 37): its structure (every primitive in one leaf, boxes that hold their
// children, at most eight children, the depth bound), the same hierarchy for any thread count, the
// same hits on every SIMD level, and the same pictures as the KD tree. Its agreement with the naive
// list ray by ray is in accel_agreement_test.cpp, with the trees'.
#include "accel/bvh.h"

#include <omp.h>

#include <cstring>
#include <set>
#include <sstream>

#include "accel/build.h"
#include "accel/build_chunks.h"
#include "accel/bvh_tree.h"
#include "accel/naive.h"
#include "core/random.h"
#include "core/simd.h"
#include "render/renderer.h"
#include "scene/generate.h"
#include "scene/thesis_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

std::string bvhDump(const Accelerator& bvh) {
    std::ostringstream out;
    out.precision(17);
    bvh.forEachNode([&](const TreeNodeInfo& n) {
        out << n.id << ' ' << n.depth << ' ' << n.leaf << ' ' << n.primitives << ' ' << n.bounds << '\n';
    });
    return out.str();
}

// Rays from a box around the scene towards points inside it, some along the axes.
std::vector<Ray> testRays(int n, std::uint64_t seed) {
    SplitMix64 rng(seed);
    const auto uniform = [&](Real lo, Real hi) { return lo + (hi - lo) * Real(rng.uniform()); };
    std::vector<Ray> rays;
    for (int i = 0; i < n; ++i) {
        const Vec3 from{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
        Vec3 direction = normalize(Vec3{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)} - from * Real(0.5));
        if (i % 5 == 0) direction = Vec3{0, 0, 0}, direction[i / 5 % 3] = i % 2 ? 1 : -1;
        rays.push_back({from, direction});
    }
    return rays;
}

// The hits and shadow answers of `rays`, with the work counted, in one string.
std::string trace(const Accelerator& accel, const std::vector<Ray>& rays, RayCounters& counters) {
    std::ostringstream out;
    out.precision(17);
    for (const Ray& ray : rays) {
        Hit hit;
        if (accel.intersect(ray, kInfinity, hit, counters))
            out << hit.prim << ' ' << hit.t << ' ' << hit.u << ' ' << hit.v;
        out << ' ' << accel.occluded(ray, Real(1.5), counters) << '\n';
    }
    return out.str();
}

bool contains(const Aabb& outer, const Aabb& inner) {
    for (int a = 0; a < 3; ++a)
        if (inner.lo[a] < outer.lo[a] || inner.hi[a] > outer.hi[a]) return false;
    return true;
}

}  // namespace

TEST(Bvh, EveryPrimitiveLiesInOneLeafInsideEveryBoxAboveIt) {
    const Primitives prims = generateScene({3000, 500, Placement::Clustered, 3, 200, 200}).primitives;
    const auto bvh = buildBvh(prims, BvhSettings{});
    const AccelStats s = bvh->stats();
    EXPECT_EQ(s.name, "bvh");
    EXPECT_EQ(s.primitiveReferences, prims.size());  // no primitive twice, none left out
    EXPECT_EQ(s.primitives, prims.size());
    EXPECT_GT(s.leaves, prims.size() / 8);
    EXPECT_LE(s.averagePrimitivesPerLeaf, 8.0);
    // Each node's box (its parent's slot) holds its children's, so every primitive's leaf box and
    // each box above it hold the primitive; the root's holds the scene.
    std::vector<Aabb> path;
    std::vector<int> childrenOf;
    bvh->forEachNode([&](const TreeNodeInfo& n) {
        path.resize(n.depth);
        if (n.depth == 0) {
            EXPECT_TRUE(contains(n.bounds, prims.bounds()));
        } else {
            EXPECT_TRUE(contains(path.back(), n.bounds)) << "node " << n.id;
            ++childrenOf[n.depth - 1];
        }
        EXPECT_TRUE(!n.leaf || n.primitives <= 8u) << "node " << n.id;
        path.push_back(n.bounds);
        childrenOf.resize(n.depth + 1);
        childrenOf[n.depth] = 0;
        for (std::size_t d = 0; d + 1 < childrenOf.size(); ++d) EXPECT_LE(childrenOf[d], kBvhWidth);
    });
    // Every inner node has two children or more (the root of a one-leaf scene aside).
    EXPECT_LE(s.nodes - s.leaves, s.leaves);
    EXPECT_GE(s.memoryBytes, (s.nodes - s.leaves) * sizeof(BvhNode));
}

// Thousands of primitives with one centre: no plane parts them, so the build halves them as they
// lie, and the depth stays within the traversal's stack.
TEST(Bvh, CoincidentPrimitivesEndInSmallLeavesAndAShallowHierarchy) {
    Primitives prims;
    for (int i = 0; i < 20000; ++i) prims.add<Triangle>({{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}}, 0);
    const auto bvh = buildBvh(prims, BvhSettings{});
    EXPECT_LE(bvh->stats().maxDepth, std::uint32_t(kMaxBvhDepth));
    EXPECT_EQ(bvh->stats().primitiveReferences, prims.size());
    bvh->forEachNode([&](const TreeNodeInfo& n) { EXPECT_TRUE(!n.leaf || n.primitives <= 8u) << "node " << n.id; });
    Hit hit;
    RayCounters counters;
    ASSERT_TRUE(bvh->intersect({{0, 0, 1}, {0, 0, -1}}, kInfinity, hit, counters));
    EXPECT_EQ(hit.t, 1);
    EXPECT_TRUE(bvh->occluded({{0, 0, 1}, {0, 0, -1}}, 2, counters));
    EXPECT_FALSE(bvh->occluded({{0, 0, 1}, {0, 0, -1}}, Real(0.5), counters));
}

TEST(Bvh, EmptyAndSinglePrimitiveScenes) {
    const Primitives none;
    const auto empty = buildBvh(none, BvhSettings{});
    Hit hit;
    RayCounters counters;
    EXPECT_FALSE(empty->intersect({{0, 0, 1}, {0, 0, -1}}, kInfinity, hit, counters));
    EXPECT_FALSE(empty->occluded({{0, 0, 1}, {0, 0, -1}}, kInfinity, counters));
    EXPECT_EQ(empty->stats().nodes, 0u);
    Primitives one;
    one.add<Sphere>({{0, 0, 0}, 1}, 0);
    const auto single = buildBvh(one, BvhSettings{});
    ASSERT_TRUE(single->intersect({{0, 0, 5}, {0, 0, -1}}, kInfinity, hit, counters));
    EXPECT_EQ(hit.t, 4);
    EXPECT_FALSE(single->intersect({{0, 2, 5}, {0, 0, -1}}, kInfinity, hit, counters));
    EXPECT_EQ(single->stats().leaves, 1u);
    EXPECT_EQ(single->stats().nodes, 1u);  // the leaf alone, as rt-inspect shows it
}

TEST(Bvh, SameHierarchyAndHitsForAnyNumberOfThreads) {
    const Primitives prims = generateScene({60000, 2000, Placement::Uniform, 6}).primitives;  // tasks below the root
    ASSERT_GE(prims.size(), 2 * kTaskPrimitives);
    const std::vector<Ray> rays = testRays(2000, 5);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const auto one = buildBvh(prims, BvhSettings{});
    omp_set_num_threads(3);
    const auto three = buildBvh(prims, BvhSettings{});
    omp_set_num_threads(threads);
    EXPECT_EQ(bvhDump(*one), bvhDump(*three));
    RayCounters a, b;
    EXPECT_EQ(trace(*one, rays, a), trace(*three, rays, b));
}

// The slab tests and the leaves run on each level's lanes: the same hits, bit for bit, and the
// same work counted.
TEST(Bvh, SameHitsAndCountsOnEverySimdLevel) {
    const Primitives prims = generateScene({4000, 800, Placement::Clustered, 8, 300, 300}).primitives;
    const auto bvh = buildBvh(prims, BvhSettings{});
    const std::vector<Ray> rays = testRays(20000, 9);
    const SimdLevel before = simdLevel();
    ASSERT_TRUE(setSimdLevel(SimdLevel::sse2));
    RayCounters baseCounters;
    const std::string base = trace(*bvh, rays, baseCounters);
    for (SimdLevel level : kSimdLevels) {
        if (!setSimdLevel(level)) continue;
        RayCounters counters;
        EXPECT_EQ(trace(*bvh, rays, counters), base) << simdLevelName(level);
        EXPECT_EQ(counters.traversalSteps, baseCounters.traversalSteps) << simdLevelName(level);
        EXPECT_EQ(counters.intersectionTests, baseCounters.intersectionTests) << simdLevelName(level);
    }
    setSimdLevel(before);
}

// The nearest-first order and the early exit of shadow rays save most of the naive list's work.
TEST(Bvh, CountsItsWorkAndSavesMostTests) {
    const Primitives prims = generateScene({20000, 1000, Placement::Clustered, 4}).primitives;
    const auto bvh = buildBvh(prims, BvhSettings{});
    const std::vector<Ray> rays = testRays(2000, 7);
    RayCounters nearest, shadow;
    Hit hit;
    for (const Ray& ray : rays) {
        bvh->intersect(ray, kInfinity, hit, nearest);
        bvh->occluded(ray, kInfinity, shadow);
    }
    EXPECT_GT(nearest.traversalSteps, rays.size());
    EXPECT_LT(nearest.intersectionTests, rays.size() * 200);
    EXPECT_LT(shadow.intersectionTests, nearest.intersectionTests);  // any hit stops at the first
}

// Pictures of the thesis scenes through the BVH and the KD tree: the same bits (the two find the
// same nearest hits; they differ only in the work, which the picture does not show).
TEST(Bvh, ThesisScenesLookAsThroughTheKdTree) {
    for (const auto name : {"balls", "ships", "tree", "pyramid5"}) {
        SCOPED_TRACE(name);
        const Scene scene = thesisScene(name);
        AccelSettings kd, bvh;
        bvh.kind = AccelKind::Bvh;
        RenderSettings r;
        r.width = 96;
        r.height = 64;
        r.shadows = true;
        r.reflectionDepth = 3;
        RenderStats kdStats, bvhStats;
        const Framebuffer a = render(scene, *buildAccelerator(scene.primitives, kd), r, kdStats);
        const Framebuffer b = render(scene, *buildAccelerator(scene.primitives, bvh), r, bvhStats);
        ASSERT_EQ(a.pixels().size(), b.pixels().size());
        EXPECT_EQ(std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Color)), 0);
        EXPECT_EQ(kdStats.counters.camera.rays, bvhStats.counters.camera.rays);
        EXPECT_EQ(kdStats.counters.shadow.rays, bvhStats.counters.shadow.rays);
        EXPECT_EQ(kdStats.counters.reflection.rays, bvhStats.counters.reflection.rays);
    }
}
