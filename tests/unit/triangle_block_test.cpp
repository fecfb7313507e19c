// The leaves' block test (geometry/triangle_block.h) against the scalar triangle test: the
// same hits with the same bits, lane by lane, including the cases the scalar test rejects
// early (parallel rays, edges, behind the origin, beyond tMax).
#include "geometry/triangle_block.h"

#include <random>

#include "test_util.h"

using namespace rt;

namespace {

// Tests `tris` (kSimdWidth of them) as one block and one by one; returns the lanes that differ.
int differingLanes(const Triangle* tris, const Ray& ray, Real tMax) {
    TriangleBlock block;
    for (int lane = 0; lane < kSimdWidth; ++lane) block.set(lane, tris[lane], std::uint32_t(lane));
    const BlockHits hits = intersectBlock(block, RayLanes(ray), tMax);
    int differing = 0;
    for (int lane = 0; lane < kSimdWidth; ++lane) {
        Real t, u, v;
        const bool hit = intersectTriangle(tris[lane], ray, tMax, t, u, v);
        const bool laneHit = (hits.lanes >> lane) & 1u;
        differing += hit != laneHit || (hit && (t != hits.t[lane] || u != hits.u[lane] || v != hits.v[lane]));
    }
    return differing;
}

}  // namespace

TEST(TriangleBlock, LanesHaveTheScalarTestsBits) {
    std::mt19937 gen(5);
    std::uniform_real_distribution<Real> coord(-1, 1);
    const auto point = [&] { return Vec3{coord(gen), coord(gen), coord(gen)}; };
    int hits = 0, differing = 0;
    for (int i = 0; i < 50000; ++i) {
        Triangle tris[kSimdWidth];
        for (Triangle& tri : tris) tri = {point(), point(), point()};
        const Ray ray{point(), normalize(point())};
        differing += differingLanes(tris, ray, i % 2 ? kInfinity : Real(0.5));
        for (const Triangle& tri : tris) hits += intersectsAny(tri, ray, kInfinity);
    }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(hits, 2000);  // enough hits to compare
}

TEST(TriangleBlock, EdgesParallelRaysAndEmptyLanes) {
    // Two triangles sharing the edge x = 0 in the plane z = 0, one in a plane the ray runs in.
    const Triangle left{{0, -1, 0}, {0, 1, 0}, {-1, 0, 0}}, right{{0, -1, 0}, {1, 0, 0}, {0, 1, 0}};
    const Triangle parallel{{-1, 0, -1}, {1, 0, -1}, {0, 0, 1}};
    Triangle tris[kSimdWidth];
    for (int lane = 0; lane < kSimdWidth; ++lane) tris[lane] = lane % 3 == 0 ? left : lane % 3 == 1 ? right : parallel;
    EXPECT_EQ(differingLanes(tris, {{0, 0, 1}, {0, 0, -1}}, kInfinity), 0);   // down the shared edge
    EXPECT_EQ(differingLanes(tris, {{-2, 0, 0}, {1, 0, 0}}, kInfinity), 0);   // in the plane z = 0 and y = 0
    EXPECT_EQ(differingLanes(tris, {{0, 0, -1}, {0, 0, -1}}, kInfinity), 0);  // all behind

    TriangleBlock empty;  // no triangle set: no lane hits, whatever the ray
    EXPECT_EQ(intersectBlock(empty, RayLanes({{0, 0, 0}, {0, 0, 1}}), kInfinity).lanes, 0u);
    EXPECT_EQ(empty.id[0], TriangleBlock::kNoPrimitive);
}
