// The KD tree's SAH model, split finders, limits and determinism (thesis 2.5.1).
#include "accel/kdtree.h"

#include <omp.h>

#include <algorithm>
#include <limits>
#include <random>
#include <sstream>

#include "accel/build_chunks.h"
#include "accel/kd_split.h"
#include "core/simd.h"
#include "geometry/triangle_block.h"
#include "scene/generate.h"
#include "test_util.h"

using namespace rt;

namespace {

std::string kdDump(const Accelerator& tree) {
    std::ostringstream out;
    tree.forEachNode([&](const TreeNodeInfo& n) {
        out << n.id << ' ' << n.depth << ' ' << n.leaf << ' ' << (n.plane ? n.plane->axis : -1) << ' '
            << (n.plane ? n.plane->position : 0) << ' ' << n.primitives << '\n';
    });
    return out.str();
}

KdSettings withMethod(KdSplitMethod method) {
    KdSettings s;
    s.splitMethod = method;
    return s;
}

std::vector<FloatBox> randomBoxes(int n, std::uint32_t seed) {
    std::mt19937 gen(seed);
    std::uniform_int_distribution<int> grid(0, 8);  // on a grid, so positions repeat and planars occur
    std::vector<FloatBox> boxes;
    for (int i = 0; i < n; ++i) {
        FloatBox b;
        for (int a = 0; a < 3; ++a) {
            const int x = grid(gen), y = grid(gen);
            b.lo[a] = float(std::min(x, y)) / 8;
            b.hi[a] = float(std::max(x, y)) / 8;
        }
        boxes.push_back(b);
    }
    return boxes;
}

}  // namespace

TEST(SahModel, CostOfASplit) {
    KdSettings settings;
    settings.traversalCost = 1;
    settings.intersectionCost = 1.5;
    settings.emptyBonus = 0.8;
    const SahModel sah(Aabb{{0, 0, 0}, {1, 1, 1}}, settings);
    SahSplit best;
    sah.consider(0, 0.5f, 4, 6, 0, best);  // each half has 4/6 of the area
    EXPECT_EQ(best.axis, 0);
    EXPECT_NEAR(best.cost, 1 + 1.5 * (4.0 / 6 * 4 + 4.0 / 6 * 6), 1e-9);
    sah.consider(1, 0.25f, 0, 10, 0, best);  // cuts off empty space: the bonus applies
    EXPECT_EQ(best.axis, 1);
    EXPECT_NEAR(best.cost, 0.8 * (1 + 1.5 * (5.0 / 6 * 10)), 1e-9);
    sah.consider(2, 0.0f, 0, 10, 0, best);  // on the voxel's face: cuts off nothing, ignored
    EXPECT_EQ(best.axis, 1);
    // Two primitives lying in the plane y = 0.75 join the cheaper, smaller upper side.
    SahSplit planar;
    sah.consider(1, 0.75f, 6, 2, 2, planar);
    EXPECT_FALSE(planar.planarBelow);
    EXPECT_NEAR(planar.cost, 1 + 1.5 * (5.0 / 6 * 6 + 3.0 / 6 * 4), 1e-9);  // below: 5/6 of the area
    EXPECT_DOUBLE_EQ(sah.leafCost(10), 15);
}

// The sweep must find the cheapest of all planes at box edges, as counting every
// candidate directly (the O(N^2) method the thesis starts from) does.
TEST(KdSplit, SweepAndSamplingMatchDirectCounting) {
    const std::vector<FloatBox> boxes = randomBoxes(60, 8);
    const Aabb voxel{{0, 0, 0}, {1, 1, 1}};
    const SahModel sah(voxel, KdSettings{});
    auto direct = [&](const std::vector<float>& candidates) {
        SahSplit best;
        for (int axis = 0; axis < 3; ++axis) {
            for (float p : candidates) {
                for (bool planarBelow : {true, false}) {
                    std::size_t below = 0, above = 0;
                    for (const FloatBox& b : boxes) {
                        below += b.below(axis, p, planarBelow);
                        above += b.above(axis, p, planarBelow);
                    }
                    sah.consider(axis, p, below, above, 0, best);
                }
            }
        }
        return best;
    };
    std::vector<float> edges;
    for (int k = 0; k <= 8; ++k) edges.push_back(float(k) / 8);
    const SahSplit expected = direct(edges);
    const SahSplit sorted = findSplitBySorting(boxes, sah);
    EXPECT_EQ(sorted.axis, expected.axis);
    EXPECT_EQ(sorted.pos, expected.pos);
    EXPECT_DOUBLE_EQ(sorted.cost, expected.cost);

    // Seven samples fall exactly on the grid planes 1/8 .. 7/8 (and some boxes lie in them).
    const SahSplit sampled = findSplitBySampling(boxes, voxel, 7, sah);
    EXPECT_DOUBLE_EQ(sampled.cost, expected.cost);
    const SahSplit fewer = findSplitBySampling(boxes, voxel, 3, sah);  // planes 1/4, 1/2, 3/4
    EXPECT_DOUBLE_EQ(fewer.cost, direct({0.25f, 0.5f, 0.75f}).cost);
}

// Binning's planes run from the boxes' lowest bound to their highest, so on a grid of
// eighths it sees every box edge, and the empty space beyond the boxes is cut off at its
// border, as by the exact sweep.
TEST(KdSplit, BinningFindsTheSweepsPlaneOnAGrid) {
    const std::vector<FloatBox> boxes = randomBoxes(60, 8);
    for (const Aabb voxel : {Aabb{{0, 0, 0}, {1, 1, 1}}, Aabb{{0, -1, 0}, {2, 1, 3}}}) {
        const SahModel sah(voxel, KdSettings{});
        const SahSplit sorted = findSplitBySorting(boxes, sah);
        const SahSplit binned = findSplitByBinning(boxes, 8, sah);
        EXPECT_EQ(binned.axis, sorted.axis);
        EXPECT_EQ(binned.pos, sorted.pos);
        EXPECT_DOUBLE_EQ(binned.cost, sorted.cost);
        // Fewer bins see fewer planes: never a cheaper one.
        EXPECT_GE(findSplitByBinning(boxes, 3, sah).cost, sorted.cost);
    }
}

// Binning counts its boxes 16 at a time on AVX-512 (kd_split.cpp), with a guess of each bound's
// plane that a check then confirms or hands to the scalar search: every level must count the same.
// The boxes hold bounds on the planes, boxes lying in a plane, far-off clusters whose float planes
// collapse (so that guesses miss by more than a step), and bounds of inf and NaN.
TEST(KdSplit, BinningCountsTheSameOnEverySimdLevel) {
    std::mt19937 gen(31);
    std::uniform_real_distribution<float> unit(0, 1);
    std::vector<FloatBox> boxes = randomBoxes(500, 12);  // on a grid of eighths: on binning's planes
    for (int i = 0; i < 700; ++i) {
        FloatBox b;
        for (int a = 0; a < 3; ++a) {
            const float x = unit(gen), y = i % 5 == 0 ? x : unit(gen);  // every fifth box lies in a plane
            b.lo[a] = std::min(x, y);
            b.hi[a] = std::max(x, y);
        }
        boxes.push_back(b);
    }
    std::vector<FloatBox> far;  // planes 1e-4 apart near 1e4, where a float's step is 1e-3
    for (int i = 0; i < 300; ++i) {
        FloatBox b;
        for (int a = 0; a < 3; ++a) b.lo[a] = b.hi[a] = 1e4f + 3e-3f * unit(gen);
        far.push_back(b);
    }
    std::vector<FloatBox> odd = boxes;  // bounds that are not finite
    for (std::size_t i = 0; i < odd.size(); i += 37) odd[i].hi[i % 3] = std::numeric_limits<float>::infinity();
    for (std::size_t i = 5; i < odd.size(); i += 41) odd[i].lo[i % 3] = -std::numeric_limits<float>::infinity();
    for (std::size_t i = 9; i < odd.size(); i += 43) odd[i].lo[i % 3] = std::numeric_limits<float>::quiet_NaN();
    const SimdLevel before = simdLevel();
    for (const std::vector<FloatBox>* set : {&boxes, &far, &odd}) {
        const Aabb voxel =
            set == &far ? Aabb{{1e4, 1e4, 1e4}, {1e4 + 4e-3, 1e4 + 4e-3, 1e4 + 4e-3}} : Aabb{{0, 0, 0}, {1, 1, 1}};
        const SahModel sah(voxel, KdSettings{});
        for (int bins : {3, 8, 32, 45, 46}) {  // 45 bins: 48 guarded planes, the most the lanes take
            ASSERT_TRUE(setSimdLevel(SimdLevel::sse2));
            const SahSplit scalar = findSplitByBinning(*set, bins, sah);
            const SahSplit sampled = findSplitBySampling(*set, voxel, bins, sah);
            for (SimdLevel level : kSimdLevels) {
                if (!setSimdLevel(level)) continue;
                const SahSplit binned = findSplitByBinning(*set, bins, sah);
                EXPECT_EQ(binned.axis, scalar.axis) << simdLevelName(level) << " " << bins;
                EXPECT_EQ(binned.pos, scalar.pos) << simdLevelName(level) << " " << bins;
                EXPECT_EQ(binned.cost, scalar.cost) << simdLevelName(level) << " " << bins;
                EXPECT_EQ(findSplitBySampling(*set, voxel, bins, sah).cost, sampled.cost) << simdLevelName(level);
            }
        }
    }
    setSimdLevel(before);
}

// The same through whole trees that bin down to nodes of 16 primitives: every split chosen the same.
TEST(KdTree, BinnedTreesAreTheSameOnEverySimdLevel) {
    Primitives prims = generateScene({3000, 500, Placement::Clustered, 14}).primitives;
    KdSettings settings;
    settings.binningMinimum = 16;
    const SimdLevel before = simdLevel();
    ASSERT_TRUE(setSimdLevel(SimdLevel::sse2));
    const std::string scalar = kdDump(*buildKdTree(prims, settings));
    for (SimdLevel level : kSimdLevels) {
        if (setSimdLevel(level)) {
            EXPECT_EQ(kdDump(*buildKdTree(prims, settings)), scalar) << simdLevelName(level);
        }
    }
    setSimdLevel(before);
}

TEST(KdSplit, RadixSortOrdersEventsAsOperatorLess) {
    std::mt19937 gen(9);
    std::uniform_int_distribution<int> pick(0, 9);
    const float positions[] = {-1e30f, -2.5f, -1.0f, -0.0f, 0.0f, 1e-40f, 0.5f, 0.5f, 3.0f, 1e30f};
    SplitEvents events;
    for (std::uint32_t i = 0; i < 5000; ++i)
        events.emplace_back(positions[pick(gen)], i, SplitEvent::Type(pick(gen) % 3));
    SplitEvents expected = events;
    std::stable_sort(expected.begin(), expected.end());
    radixSortEvents(events);
    ASSERT_EQ(events.size(), expected.size());
    for (std::size_t i = 0; i < events.size(); ++i) {
        // Equal positions and types may come in any order; -0 and +0 are equal positions.
        EXPECT_EQ(events[i].pos, expected[i].pos) << i;
        EXPECT_EQ(events[i].type(), expected[i].type()) << i;
    }
}

TEST(KdTree, SweepAndSortBuildTheSameTree) {
    const Primitives prims = generateScene({1500, 300, Placement::Clustered, 5}).primitives;
    const auto sweep = buildKdTree(prims, withMethod(KdSplitMethod::Sweep));
    const auto sort = buildKdTree(prims, withMethod(KdSplitMethod::Sort));
    EXPECT_EQ(kdDump(*sweep), kdDump(*sort));
    EXPECT_EQ(sweep->stats().name, "kd-sweep");
    EXPECT_GT(sweep->stats().nodes, 100u);
    // Sampling evaluates fewer planes: never a cheaper tree than the exact search here.
    EXPECT_GE(buildKdTree(prims, withMethod(KdSplitMethod::Sample))->stats().sahCost, sweep->stats().sahCost);
}

// Min-max binning in the large nodes (KdSettings::binningMinimum) costs little tree quality:
// here every node of 64 primitives or more bins.
TEST(KdTree, BinningKeepsTheSahCostClose) {
    const Primitives prims = generateScene({20000, 2000, Placement::Clustered, 11}).primitives;
    KdSettings exact;
    exact.binningMinimum = prims.size() + 1;
    KdSettings binned;
    binned.binningMinimum = 64;
    const double exactCost = buildKdTree(prims, exact)->stats().sahCost;
    EXPECT_NEAR(buildKdTree(prims, binned)->stats().sahCost, exactCost, 0.02 * exactCost);
}

// Clusters of small triangles on a ground 1,000 times their scene's size, as the tree scene's
// foliage above its ground: deep in the clusters the SAH finds split after split that lowers
// the expected cost per ray by next to nothing (KdSettings::minimumGain).
TEST(KdTree, SkipsSplitsThatGainNextToNothing) {
    Primitives prims = generateScene({20000, 0, Placement::Clustered, 12}).primitives;
    prims.add<Triangle>({{-1000, -1000, -1}, {1000, -1000, -1}, {0, 1000, -1}}, 0);
    KdSettings everySplit;
    everySplit.minimumGain = 0;
    const AccelStats all = buildKdTree(prims, everySplit)->stats();
    const AccelStats gaining = buildKdTree(prims, KdSettings{})->stats();
    EXPECT_LT(gaining.nodes, all.nodes * 3 / 4);
    EXPECT_LT(gaining.sahCost, all.sahCost * 1.001);
}

TEST(KdTree, SameTreeForAnyNumberOfThreads) {
    const Primitives prims = generateScene({50000, 0, Placement::Uniform, 6}).primitives;  // tasks below the root
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const std::string one = kdDump(*buildKdTree(prims, KdSettings{}));
    omp_set_num_threads(3);
    const std::string three = kdDump(*buildKdTree(prims, KdSettings{}));
    omp_set_num_threads(threads);
    EXPECT_EQ(one, three);
}

// The top levels' passes run in chunks on all threads (accel/build_chunks.h): the binning's
// counts, the sorting to the children, the clipping of straddling primitives and, with
// events carried from the root, the sort of each axis. Clusters of every kind under large
// triangles across the scene, so that the large nodes clip hundreds of primitives; built
// with binning at the top, with the exact sweep from the root, and with sampling.
TEST(KdTree, SameTreeForAnyNumberOfThreadsInTheTopLevels) {
    Primitives prims = generateScene({26000, 5000, Placement::Clustered, 21, 1500, 1500}).primitives;
    std::mt19937 gen(22);
    std::uniform_real_distribution<double> coordinate(-1, 1);
    const auto point = [&] { return Vec3(coordinate(gen), coordinate(gen), coordinate(gen)); };
    for (int i = 0; i < 150; ++i) prims.add<Triangle>({point(), point(), point()}, 0);
    ASSERT_GE(prims.size(), 2 * kTaskPrimitives);  // the root and its children work in chunks
    KdSettings sweepFromTheRoot;
    sweepFromTheRoot.binningMinimum = prims.size() + 1;
    const int threads = omp_get_max_threads();
    for (const KdSettings& settings : {KdSettings{}, sweepFromTheRoot, withMethod(KdSplitMethod::Sample)}) {
        omp_set_num_threads(1);
        const std::string one = kdDump(*buildKdTree(prims, settings));
        for (const int n : {2, 3}) {
            omp_set_num_threads(n);
            EXPECT_EQ(one, kdDump(*buildKdTree(prims, settings)))
                << n << " threads, " << kdSplitMethodName(settings.splitMethod) << ", binning from "
                << settings.binningMinimum;
        }
    }
    omp_set_num_threads(threads);
}

TEST(KdTree, DepthLimitGrowsWithLogN) {
    EXPECT_EQ(defaultKdMaxDepth(1), 8);
    EXPECT_EQ(defaultKdMaxDepth(1024), 21);  // 8 + 1.3 * 10
    EXPECT_EQ(defaultKdMaxDepth(1000000), 34);
    const Primitives prims = generateScene({3000, 0, Placement::Clustered, 7}).primitives;
    KdSettings shallow;
    shallow.maxDepth = 4;
    EXPECT_LE(buildKdTree(prims, shallow)->stats().maxDepth, 4u);
    EXPECT_LE(buildKdTree(prims, KdSettings{})->stats().maxDepth, std::uint32_t(defaultKdMaxDepth(prims.size())));
}

TEST(KdTree, LeafWhenNoSplitBeatsIt) {
    Primitives one;
    one.add<Triangle>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, 0);
    EXPECT_EQ(buildKdTree(one, KdSettings{})->stats().nodes, 1u);
    const Primitives prims = generateScene({500, 0, Placement::Uniform, 8}).primitives;
    KdSettings costlyTraversal;
    costlyTraversal.traversalCost = 1e6;
    EXPECT_EQ(buildKdTree(prims, costlyTraversal)->stats().nodes, 1u);
    EXPECT_GT(buildKdTree(prims, KdSettings{})->stats().nodes, 1u);
}

TEST(KdTree, CutsOffEmptySpaceFirst) {
    // A cluster in one corner of a large, otherwise empty scene (its far corner is one
    // tiny sphere): the first planes wrap the cluster, leaving large empty leaves.
    Primitives prims = generateScene({2000, 0, Placement::Uniform, 9}).primitives;
    const Aabb cluster = prims.bounds();
    prims.add<Sphere>({{20, 20, 20}, Real(0.01)}, 0);
    const auto tree = buildKdTree(prims, KdSettings{});
    std::vector<TreeNodeInfo> nodes;
    tree->forEachNode([&](const TreeNodeInfo& n) { nodes.push_back(n); });
    ASSERT_GT(nodes.size(), 3u);
    EXPECT_FALSE(nodes[0].leaf);
    ASSERT_TRUE(nodes[0].plane);
    EXPECT_NEAR(nodes[0].plane->position, cluster.hi[nodes[0].plane->axis],
                1e-3);  // the cluster's far face, not the middle
    const AccelStats s = tree->stats();
    EXPECT_GT(s.emptyLeaves, 0u);
    EXPECT_LT(s.sahCost, 0.5 * 1.5 * double(prims.size()));
}

TEST(KdTree, StatisticsAddUp) {
    const Primitives prims = generateScene({3000, 500, Placement::Uniform, 10}).primitives;
    const auto tree = buildKdTree(prims, KdSettings{});
    const AccelStats s = tree->stats();
    std::uint64_t references = 0, nonEmpty = 0;
    double depthSum = 0;
    tree->forEachNode([&](const TreeNodeInfo& n) {
        if (!n.leaf) return;
        references += n.primitives;
        nonEmpty += n.primitives > 0;
        depthSum += n.depth;
    });
    EXPECT_EQ(s.nodes, 2 * s.leaves - 1);
    EXPECT_EQ(s.primitiveReferences, references);
    EXPECT_DOUBLE_EQ(s.averagePrimitivesPerLeaf, double(references) / double(nonEmpty));
    EXPECT_DOUBLE_EQ(s.averageLeafDepth, depthSum / double(s.leaves));
    EXPECT_EQ(s.primitives, prims.size());
    EXPECT_LT(s.averagePrimitivesPerLeaf, 8);
    // Below 64 bytes per primitive for the nodes and indices, besides the leaves' copies of
    // their triangles (at most one block per reference).
    EXPECT_LT(s.bytesPerPrimitive(), 64 + double(sizeof(TriangleBlock) * s.primitiveReferences) / double(s.primitives));
    EXPECT_GT(s.buildSeconds, 0);
}
