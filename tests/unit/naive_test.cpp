#include "accel/naive.h"

#include "test_util.h"

using namespace rt;

TEST(NaiveAccelerator, FindsTheNearestOfSeveral) {
    Primitives prims;
    prims.add<Sphere>({{0, 0, 10}, 1}, 0);
    prims.add<Sphere>({{0, 0, 5}, 1}, 0);
    prims.add<Triangle>({{-1, -1, 7}, {1, -1, 7}, {0, 1, 7}}, 0);
    NaiveAccelerator naive(prims);
    RayCounters counters;
    Hit hit;
    ASSERT_TRUE(naive.intersect({{0, 0, 0}, {0, 0, 1}}, kInfinity, hit, counters));
    EXPECT_NEAR(hit.t, 4, kTol);
    EXPECT_EQ(hit.prim, 2u);  // the sphere at z = 5 (triangles come first in the ids)
    EXPECT_EQ(counters.intersectionTests, 3u);
}

TEST(NaiveAccelerator, OccludedOnlyCloserThanTMax) {
    Primitives prims;
    prims.add<Sphere>({{0, 0, 10}, 1}, 0);
    NaiveAccelerator naive(prims);
    RayCounters counters;
    EXPECT_TRUE(naive.occluded({{0, 0, 0}, {0, 0, 1}}, 20, counters));
    EXPECT_FALSE(naive.occluded({{0, 0, 0}, {0, 0, 1}}, 8, counters));
    EXPECT_FALSE(naive.occluded({{0, 0, 0}, {0, 1, 0}}, kInfinity, counters));
}

TEST(NaiveAccelerator, EmptySceneHitsNothing) {
    Primitives prims;
    NaiveAccelerator naive(prims);
    RayCounters counters;
    Hit hit;
    EXPECT_FALSE(naive.intersect({{0, 0, 0}, {0, 0, 1}}, kInfinity, hit, counters));
}
