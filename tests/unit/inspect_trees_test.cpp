// rt-inspect on the real BSP and KD trees, over scenes whose trees are known in advance:
// one sphere (a single leaf) and two clusters far apart (the root splits between them).
#include <sstream>

#include "accel/build.h"
#include "inspect/color_map.h"
#include "inspect/depth_histogram.h"
#include "inspect/heatmap.h"
#include "inspect/leaf_boxes_obj.h"
#include "inspect/ray_statistics.h"
#include "inspect/tree_report.h"
#include "inspect_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// The clusters of these tests: spheres of radius 0.2, 0.5 apart.
void addCluster(Scene& scene, const Vec3& corner, int n) { addSphereCluster(scene, corner, n, Real(0.5), Real(0.2)); }

class InspectTrees : public ::testing::TestWithParam<AccelKind> {
protected:
    std::unique_ptr<Accelerator> build(const Scene& scene) const {
        AccelSettings settings;
        settings.kind = GetParam();
        return buildAccelerator(scene.primitives, settings);
    }
};

}  // namespace

TEST_P(InspectTrees, OneSphereIsOneLeaf) {
    Scene scene = sceneLookingDownZ(90);
    scene.looseObjects.add<Sphere>({{0, 0, 10}, 2}, 0);
    scene.flatten();
    const auto accel = build(scene);
    const AccelStats s = accel->stats();
    EXPECT_EQ(s.nodes, 1u);
    EXPECT_EQ(s.leaves, 1u);
    EXPECT_EQ(s.emptyLeaves, 0u);
    EXPECT_EQ(s.primitiveReferences, 1u);
    EXPECT_EQ(s.maxDepth, 0u);
    const std::vector<DepthLevel> levels = depthHistogram(*accel);
    ASSERT_EQ(levels.size(), 1u);
    EXPECT_EQ(levels[0].primitiveReferences, 1u);
    std::ostringstream obj;
    EXPECT_EQ(writeLeafBoxesObj(obj, *accel, {}), 1u);
}

TEST_P(InspectTrees, TwoClustersSplitBetweenThem) {
    Scene scene = sceneLookingDownZ(90);
    addCluster(scene, {-10, 0, 20}, 4);  // x in [-10.2, -8.3]
    addCluster(scene, {8.5, 0, 20}, 4);  // x in [8.3, 10.2]
    scene.flatten();
    const auto accel = build(scene);
    const std::vector<TreeNodeInfo> nodes = nodesOf(*accel);
    ASSERT_GE(nodes.size(), 3u);
    const TreeNodeInfo& root = nodes[0];
    ASSERT_FALSE(root.leaf);
    ASSERT_TRUE(root.plane);
    EXPECT_EQ(root.plane->axis, 0);
    EXPECT_GE(root.plane->position, Real(-8.3) - kTol);  // on a cluster's face counts as between them
    EXPECT_LE(root.plane->position, Real(8.3) + kTol);
    // Each side of the root holds one cluster: 64 spheres, perhaps referenced more than once.
    std::uint64_t left = 0, right = 0;
    bool inRight = false;
    for (std::size_t i = 1; i < nodes.size(); ++i) {
        if (nodes[i].depth == 1 && i > 1) inRight = true;
        if (nodes[i].leaf) (inRight ? right : left) += nodes[i].primitives;
    }
    EXPECT_GE(left, 64u);
    EXPECT_GE(right, 64u);
    EXPECT_EQ(left + right, accel->stats().primitiveReferences);

    const std::vector<DepthLevel> levels = depthHistogram(*accel);
    std::uint64_t nodeCount = 0, leafCount = 0;
    for (const DepthLevel& l : levels) nodeCount += l.nodes, leafCount += l.leaves;
    EXPECT_EQ(nodeCount, accel->stats().nodes);
    EXPECT_EQ(leafCount, accel->stats().leaves);
    EXPECT_EQ(levels.size() - 1, accel->stats().maxDepth);
}

TEST_P(InspectTrees, DenseClusterIsHottest) {
    Scene scene = sceneLookingDownZ(60);
    addCluster(scene, {3.25, -1.75, 20}, 8);  // 512 spheres, on the left of the picture (+x is left)
    for (const Real x : {Real(-8), Real(-4), Real(0)}) scene.looseObjects.add<Sphere>({{x, 0, 20}, Real(1.5)}, 0);
    scene.flatten();
    const auto accel = build(scene);
    const int w = 120, h = 90;
    RenderSettings picture;
    picture.width = w;
    picture.height = h;
    const std::vector<float> cost = pixelWork(scene, *accel, picture, PixelRays::Camera);
    const auto hottest = std::max_element(cost.begin(), cost.end()) - cost.begin();
    EXPECT_LT(hottest % w, w / 2) << "hottest pixel at " << hottest % w << "," << hottest / w;
    const RgbImage image = renderHeatmap(cost, w, h, {});
    EXPECT_EQ(image.at(int(hottest % w), int(hottest / w)), viridis(1));
}

TEST_P(InspectTrees, RaysOfAPicture) {
    Scene scene = sceneLookingDownZ(90);
    addCluster(scene, {-1, -1, 8}, 4);
    scene.lights.push_back({{0, 0, 0}});
    scene.flatten();
    const auto accel = build(scene);
    RenderSettings options;
    options.width = 40;
    options.height = 30;
    options.shadows = true;
    const RenderCounters rays = traceRayStatistics(scene, *accel, options);
    EXPECT_EQ(rays.camera.rays, 1200u);
    EXPECT_GT(rays.shadow.rays, 0u);
    EXPECT_GT(rays.camera.traversalSteps, 0u);
    // A tree tests far fewer primitives per ray than the 64 of the naive list.
    EXPECT_LT(testsPerRay(rays.total()), 32.0);
}

INSTANTIATE_TEST_SUITE_P(BspAndKd, InspectTrees, ::testing::Values(AccelKind::Bsp, AccelKind::Kd),
                         [](const ::testing::TestParamInfo<AccelKind>& p) { return accelKindName(p.param); });
