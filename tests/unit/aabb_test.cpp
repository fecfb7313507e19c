#include "core/aabb.h"

#include "test_util.h"

using namespace rt;

TEST(Aabb, EmptyBoxGrowsToWhatItIsExtendedBy) {
    Aabb b;
    EXPECT_TRUE(b.empty());
    EXPECT_EQ(b.surfaceArea(), 0);
    b.extend(Vec3{1, 2, 3});
    EXPECT_FALSE(b.empty());
    EXPECT_EQ(b.lo, (Vec3{1, 2, 3}));
    b.extend(Aabb{{-1, 0, 0}, {2, 2, 4}});
    EXPECT_EQ(b, (Aabb{{-1, 0, 0}, {2, 2, 4}}));
    EXPECT_EQ(b.longestAxis(), 2);
    EXPECT_EQ(b.surfaceArea(), 2 * (3 * 2 + 2 * 4 + 4 * 3));
}

TEST(Aabb, ClipRayThroughBox) {
    const Aabb box{{-1, -1, -1}, {1, 1, 1}};
    const Ray ray{{0, 0, -5}, {0, 0, 1}};
    Real t0 = 0, t1 = kInfinity;
    ASSERT_TRUE(clipRay(box, ray, reciprocal(ray.direction), t0, t1));
    EXPECT_NEAR(t0, 4, kTol);
    EXPECT_NEAR(t1, 6, kTol);
}

TEST(Aabb, ClipRayMissesBox) {
    const Aabb box{{-1, -1, -1}, {1, 1, 1}};
    const Ray ray{{0, 2, -5}, {0, 0, 1}};  // parallel to the z axis, above the box
    Real t0 = 0, t1 = kInfinity;
    EXPECT_FALSE(clipRay(box, ray, reciprocal(ray.direction), t0, t1));
}

TEST(Aabb, ClipRayParallelToAxisStartingOnASlabPlane) {
    // The origin lies exactly on the plane y = 1 and the ray runs along it: (1 - 1) * inf is NaN.
    const Aabb box{{-1, -1, -1}, {1, 1, 1}};
    const Ray ray{{0, 1, -5}, {0, 0, 1}};
    Real t0 = 0, t1 = kInfinity;
    ASSERT_TRUE(clipRay(box, ray, reciprocal(ray.direction), t0, t1));
    EXPECT_NEAR(t0, 4, kTol);
    EXPECT_NEAR(t1, 6, kTol);
}

TEST(Aabb, ClipRayFromInsideAndBehind) {
    const Aabb box{{-1, -1, -1}, {1, 1, 1}};
    Real t0 = 0, t1 = kInfinity;
    const Ray inside{{0, 0, 0}, normalize(Vec3{1, 1, 0})};
    ASSERT_TRUE(clipRay(box, inside, reciprocal(inside.direction), t0, t1));
    EXPECT_EQ(t0, 0);
    EXPECT_NEAR(t1, std::sqrt(Real(2)), kTol);
    t0 = 0, t1 = kInfinity;
    const Ray away{{0, 0, 5}, {0, 0, 1}};
    EXPECT_FALSE(clipRay(box, away, reciprocal(away.direction), t0, t1));
}
