// Disks (geometry/disk.h): the ray test against hits worked out by hand (front, back, beyond the
// radius, edge-on, behind the origin), bounds, clipped bounds and box overlap.
#include "geometry/disk.h"

#include <random>

#include "test_util.h"

using namespace rt;

namespace {

// Radius 2 in the plane z = 1, facing +z.
const Disk kDisk{{0, 0, 1}, {0, 0, 1}, 2};

}  // namespace

TEST(Disk, HitFromTheFrontAtTheAnalyticDistance) {
    Hit hit;
    ASSERT_TRUE(intersect(kDisk, {{1, 0, 5}, {0, 0, -1}}, kInfinity, hit));
    EXPECT_EQ(hit.t, 4);
    EXPECT_EQ(hit.u, Real(0.25));  // (1 / 2)^2: the squared distance from the centre in radii
    ASSERT_TRUE(intersect(kDisk, {{0, 0, 4}, normalize(Vec3{1, 0, -3})}, kInfinity, hit));  // to (1, 0, 1)
    EXPECT_NEAR(hit.t, std::sqrt(Real(10)), 1e-5);
    EXPECT_NEAR(hit.u, 0.25, 1e-5);
    EXPECT_FALSE(intersect(kDisk, {{0, 0, 4}, normalize(Vec3{1, 0, -1})}, kInfinity, hit));  // to (3, 0, 1)
}

TEST(Disk, MissesBeyondTheRadiusAndBeforeTheOrigin) {
    Hit hit;
    EXPECT_FALSE(intersect(kDisk, {{2.001f, 0, 5}, {0, 0, -1}}, kInfinity, hit));  // just outside the rim
    EXPECT_TRUE(intersect(kDisk, {{1.999f, 0, 5}, {0, 0, -1}}, kInfinity, hit));   // just inside
    EXPECT_FALSE(intersect(kDisk, {{0, 0, 5}, {0, 0, 1}}, kInfinity, hit));        // pointing away
    EXPECT_FALSE(intersect(kDisk, {{0, 0, 5}, {0, 0, -1}}, 4, hit));               // t = 4 is not < tMax
    EXPECT_FALSE(intersectsAny(kDisk, {{0, 0, 5}, {0, 0, -1}}, Real(3.9)));
}

TEST(Disk, EdgeOnRaysMiss) {
    Hit hit;
    EXPECT_FALSE(intersect(kDisk, {{-5, 0, 1}, {1, 0, 0}}, kInfinity, hit));  // in the plane, through the centre
    EXPECT_FALSE(intersect(kDisk, {{-5, 0, 2}, {1, 0, 0}}, kInfinity, hit));  // parallel, above
}

TEST(Disk, HitFromTheBackWithTheSameNormal) {
    Hit hit;
    ASSERT_TRUE(intersect(kDisk, {{0, 1, -2}, {0, 0, 1}}, kInfinity, hit));
    EXPECT_EQ(hit.t, 3);
    expectNear(kDisk.normal({0, 1, 1}), {0, 0, 1});  // the renderer turns it towards the ray
}

TEST(Disk, BoundsAreExactForAnyNormal) {
    EXPECT_EQ(kDisk.bounds(), (Aabb{{-2, -2, 1}, {2, 2, 1}}));
    const Disk tilted{{0, 0, 0}, normalize(Vec3{1, 0, 1}), 1};
    const Aabb box = tilted.bounds();
    expectNear(box.lo, {-std::sqrt(Real(0.5)), -1, -std::sqrt(Real(0.5))});
    expectNear(box.hi, {std::sqrt(Real(0.5)), 1, std::sqrt(Real(0.5))});
    for (int i = 0; i < 64; ++i) {  // every point of the rim lies in the bounds
        const Vec3 p = tilted.surfacePoint(1, Real(i) / 64);
        EXPECT_NEAR(length(p - tilted.center), 1, 1e-5);
        EXPECT_NEAR(dot(p - tilted.center, tilted.planeNormal), 0, 1e-5);
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(p[axis], box.lo[axis] - Real(1e-5));
            EXPECT_LE(p[axis], box.hi[axis] + Real(1e-5));
        }
    }
    EXPECT_NEAR(kDisk.area(), 4 * kPi, 1e-5);
}

TEST(Disk, ClippedBoundsHoldThePartInsideAndDropBoxesThePlaneMisses) {
    // The half x >= 0: the bounds cut there.
    EXPECT_EQ(clippedBounds(kDisk, {{0, -5, -5}, {5, 5, 5}}), (Aabb{{0, -2, 1}, {2, 2, 1}}));
    // Boxes above, below and beside the plane: nothing inside.
    EXPECT_TRUE(clippedBounds(kDisk, {{-5, -5, 1.5f}, {5, 5, 5}}).empty());
    EXPECT_FALSE(overlaps(kDisk, {{-5, -5, 1.5f}, {5, 5, 5}}));
    EXPECT_FALSE(overlaps(kDisk, {{3, 3, 0}, {4, 4, 2}}));
    // A box touching the plane from below counts (closed boxes).
    EXPECT_TRUE(overlaps(kDisk, {{-1, -1, 0}, {1, 1, 1}}));
    // Tilted: a box the bounds reach but the plane does not is dropped.
    const Disk tilted{{0, 0, 0}, normalize(Vec3{1, 0, 1}), 1};
    EXPECT_TRUE(overlaps(tilted, {{-0.1f, -0.1f, -0.1f}, {0.1f, 0.1f, 0.1f}}));
    EXPECT_FALSE(overlaps(tilted, {{0.3f, -0.1f, 0.3f}, {0.7f, 0.1f, 0.7f}}));
    // Conservative: every hit on the disk lies in the clipped bounds of any box holding it.
    std::mt19937 gen(3);
    std::uniform_real_distribution<Real> coord(-1, 1);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 p = tilted.surfacePoint(std::abs(coord(gen)), std::abs(coord(gen)));
        const Aabb box{p - Vec3{0.05f, 0.05f, 0.05f} + Vec3{coord(gen), coord(gen), coord(gen)} * Real(0.04),
                       p + Vec3{0.05f, 0.05f, 0.05f}};
        const Aabb clipped = clippedBounds(tilted, box);
        ASSERT_FALSE(clipped.empty()) << i;
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_LE(clipped.lo[axis], p[axis] + Real(1e-6));
            EXPECT_GE(clipped.hi[axis], p[axis] - Real(1e-6));
        }
    }
}

TEST(Disk, ZeroRadiusOrNormalIsDegenerate) {
    EXPECT_FALSE(kDisk.degenerate());
    EXPECT_TRUE((Disk{{0, 0, 0}, {0, 0, 1}, 0}).degenerate());
    EXPECT_TRUE((Disk{{0, 0, 0}, normalize(Vec3{0, 0, 0}), 1}).degenerate());
}
