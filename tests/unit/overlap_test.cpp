// Triangle-box (Akenine-Moller) and sphere-box (Arvo) overlap, and clipping to a box.
#include "geometry/overlap.h"
#include "geometry/clip.h"

#include <random>

#include "test_util.h"

using namespace rt;

namespace {
const Aabb kUnitBox{{0, 0, 0}, {1, 1, 1}};
}  // namespace

TEST(TriangleBoxOverlap, InsideCrossingAndTouching) {
    EXPECT_TRUE(overlaps(Triangle{{0.2f, 0.2f, 0.5f}, {0.8f, 0.2f, 0.5f}, {0.5f, 0.8f, 0.5f}}, kUnitBox));
    EXPECT_TRUE(overlaps(Triangle{{-5, -5, 0.5f}, {5, -5, 0.5f}, {0, 5, 0.5f}}, kUnitBox));  // box inside it
    EXPECT_TRUE(overlaps(Triangle{{1, 0, 0}, {2, 0, 0}, {1, 1, 0}}, kUnitBox));              // touches a face
}

TEST(TriangleBoxOverlap, BoundingBoxesOverlapButTriangleMisses) {
    // The diagonal triangle's bounds cover the box corner, the triangle passes it by:
    // only the plane or an edge-cross axis separates them.
    EXPECT_FALSE(overlaps(Triangle{{1.5f, 0, 0}, {0, 1.5f, 0}, {0, 0, 1.5f}}, Aabb{{0.9f, 0.9f, 0.9f}, {1, 1, 1}}));
    EXPECT_FALSE(overlaps(Triangle{{2, -1, 0.5f}, {3, 2, 0.5f}, {-1, 2, 0.5f}}, Aabb{{0, 0, 0}, {0.4f, 0.4f, 1}}));
    EXPECT_FALSE(overlaps(Triangle{{0, 0, 2}, {1, 0, 2}, {0, 1, 2}}, kUnitBox));  // above the box
}

TEST(TriangleBoxOverlap, AgreesWithClippingOnRandomTriangles) {
    std::mt19937 gen(5);
    std::uniform_real_distribution<float> coord(-1, 2);
    int overlapping = 0;
    for (int i = 0; i < 20000; ++i) {
        const Triangle t{{coord(gen), coord(gen), coord(gen)},
                         {coord(gen), coord(gen), coord(gen)},
                         {coord(gen), coord(gen), coord(gen)}};
        const Aabb shrunk{{Real(1e-3), Real(1e-3), Real(1e-3)}, {1 - Real(1e-3), 1 - Real(1e-3), 1 - Real(1e-3)}};
        const Aabb grown{{-Real(1e-3), -Real(1e-3), -Real(1e-3)}, {1 + Real(1e-3), 1 + Real(1e-3), 1 + Real(1e-3)}};
        // Two independent methods; skip triangles that graze the box, where rounding decides.
        if (overlaps(t, shrunk) != overlaps(t, grown)) continue;
        const bool clipped = !clippedBounds(t, kUnitBox).empty();
        EXPECT_EQ(overlaps(t, kUnitBox), clipped) << t.p0 << t.p1 << t.p2;
        overlapping += clipped;
    }
    EXPECT_GT(overlapping, 2000);  // both outcomes are exercised
    EXPECT_LT(overlapping, 18000);
}

TEST(SphereBoxOverlap, HollowSphere) {
    EXPECT_TRUE(overlaps(Sphere{{0.5f, 0.5f, 0.5f}, 0.3f}, kUnitBox));
    EXPECT_TRUE(overlaps(Sphere{{2, 0.5f, 0.5f}, 1}, kUnitBox));      // touches the face x = 1
    EXPECT_FALSE(overlaps(Sphere{{2, 2, 2}, 1.5f}, kUnitBox));        // near the corner, misses it
    EXPECT_FALSE(overlaps(Sphere{{0.5f, 0.5f, 0.5f}, 5}, kUnitBox));  // the box is inside: no surface
}

TEST(ClippedBounds, TriangleAcrossTheBox) {
    // A large triangle in z = 0.5 covers the box's whole cross-section there.
    const Aabb b = clippedBounds(Triangle{{-5, -5, 0.5f}, {5, -5, 0.5f}, {0, 5, 0.5f}}, kUnitBox);
    expectNear(b.lo, {0, 0, 0.5f});
    expectNear(b.hi, {1, 1, 0.5f});
    // A triangle leaving through a corner: its part inside ends well before the bounds do.
    const Aabb c = clippedBounds(Triangle{{0.5f, 0.5f, 0.5f}, {3, 0.5f, 0.5f}, {0.5f, 3, 0.5f}}, kUnitBox);
    expectNear(c.lo, {0.5f, 0.5f, 0.5f});
    expectNear(c.hi, {1, 1, 0.5f});
    EXPECT_TRUE(clippedBounds(Triangle{{0, 0, 2}, {1, 0, 2}, {0, 1, 2}}, kUnitBox).empty());
}

// Cutting the polygon clipped to the box gives each half what clipping to that half gives,
// up to rounding (the planes are met in another order); a half the triangle misses stays empty.
TEST(ClippedBounds, SplitAgreesWithClippingEachHalf) {
    std::mt19937 gen(9);
    std::uniform_real_distribution<float> coord(-1, 2), plane(0, 1);
    int cut = 0;
    for (int i = 0; i < 20000; ++i) {
        const Triangle t{{coord(gen), coord(gen), coord(gen)},
                         {coord(gen), coord(gen), coord(gen)},
                         {coord(gen), coord(gen), coord(gen)}};
        const int axis = i % 3;
        const Real pos = plane(gen);
        Aabb below = kUnitBox, above = kUnitBox;
        below.hi[axis] = above.lo[axis] = pos;
        const SplitBounds split = splitClippedBounds(t, kUnitBox, axis, pos);
        for (const auto& [got, half] : {std::pair{split.below, below}, std::pair{split.above, above}}) {
            const Aabb want = clippedBounds(t, half);
            ASSERT_EQ(got.empty(), want.empty()) << t.p0 << t.p1 << t.p2 << " axis " << axis << " at " << pos;
            if (want.empty()) continue;
            expectNear(got.lo, want.lo, 1e-5);
            expectNear(got.hi, want.hi, 1e-5);
        }
        cut += !split.below.empty() && !split.above.empty();
    }
    EXPECT_GT(cut, 2000);  // triangles across the plane are exercised
}

TEST(ClippedBounds, SphereExactExtent) {
    // Centre on the face x = 1: inside, the ball reaches from x = 1 - r to the face.
    const Aabb b = clippedBounds(Sphere{{1, 0.5f, 0.5f}, 0.25f}, kUnitBox);
    expectNear(b.lo, {0.75f, 0.25f, 0.25f});
    expectNear(b.hi, {1, 0.75f, 0.75f});
    // Centre beyond a corner: the ball only reaches a little way into the box.
    const Aabb c = clippedBounds(Sphere{{Real(1.3), Real(1.3), Real(0.5)}, Real(0.5)}, kUnitBox);
    const Real reach = Real(1.3) - std::sqrt(Real(0.25) - Real(0.09));  // disc at distance 0.3 on the other axis
    EXPECT_NEAR(c.lo.x, reach, kTol);
    EXPECT_NEAR(c.hi.x, 1, kTol);
    EXPECT_TRUE(clippedBounds(Sphere{{0.5f, 0.5f, 0.5f}, 5}, kUnitBox).empty());
}
