// The leaves' sphere blocks (geometry/sphere_block.h) against the scalar sphere test: the same
// hits with the same bits, lane by lane, including the cases the scalar test rejects early (behind
// the origin, beside the ray, beyond tMax) and origins inside and on the surface.
#include "geometry/sphere_block.h"

#include <random>

#include "test_util.h"

using namespace rt;

namespace {

// Tests `spheres` (kSimdWidth of them) as one block and one by one; returns the lanes that differ.
int differingLanes(const Sphere* spheres, const Ray& ray, Real tMax) {
    SphereBlock block;
    for (int lane = 0; lane < kSimdWidth; ++lane) block.set(lane, spheres[lane], std::uint32_t(lane));
    const BlockHits hits = intersectBlock(block, RayLanes(ray), tMax);
    int differing = 0;
    for (int lane = 0; lane < kSimdWidth; ++lane) {
        Real t = 0;
        const bool hit = intersectSphere(spheres[lane], ray, tMax, t);
        const bool laneHit = (hits.lanes >> lane) & 1u;
        differing += hit != laneHit || (hit && (t != hits.t[lane] || hits.u[lane] != 0 || hits.v[lane] != 0));
    }
    return differing;
}

}  // namespace

TEST(SphereBlock, LanesHaveTheScalarTestsBits) {
    std::mt19937 gen(7);
    std::uniform_real_distribution<Real> coord(-1, 1), size(Real(0.05), Real(0.8));
    const auto point = [&] { return Vec3{coord(gen), coord(gen), coord(gen)}; };
    int hits = 0, differing = 0;
    for (int i = 0; i < 50000; ++i) {
        Sphere spheres[kSimdWidth];
        for (Sphere& s : spheres) s = {point(), size(gen)};
        const Ray ray{point(), normalize(point())};  // often inside a sphere
        differing += differingLanes(spheres, ray, i % 2 ? kInfinity : Real(0.5));
        for (const Sphere& s : spheres) hits += intersectsAny(s, ray, kInfinity);
    }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(hits, 5000);  // enough hits to compare
}

// Origins on the surface as rounding puts them (a shadow or reflection ray leaving a sphere): just
// inside, or just outside, where the near root can come out at t <= 0 and the far one is taken.
TEST(SphereBlock, OriginsOnTheSurfaceHaveTheScalarTestsBits) {
    std::mt19937 gen(11);
    std::uniform_real_distribution<Real> coord(-1, 1);
    const auto direction = [&] { return normalize(Vec3{coord(gen), coord(gen), coord(gen)}); };
    int differing = 0;
    for (int i = 0; i < 20000; ++i) {
        Sphere spheres[kSimdWidth];
        for (Sphere& s : spheres) s = {Vec3{coord(gen), coord(gen), coord(gen)}, Real(0.3)};
        const Ray ray{spheres[0].center + direction() * spheres[0].radius, direction()};
        differing += differingLanes(spheres, ray, kInfinity);
    }
    EXPECT_EQ(differing, 0);
}

TEST(SphereBlock, SurfaceOriginsTangentsAndEmptyLanes) {
    const Sphere unit{{0, 0, 0}, 1};
    Sphere spheres[kSimdWidth];
    for (Sphere& s : spheres) s = unit;
    EXPECT_EQ(differingLanes(spheres, {{0, 0, -1}, {0, 0, 1}}, kInfinity), 0);  // from the surface, through it
    EXPECT_EQ(differingLanes(spheres, {{0, 0, 1}, {0, 0, 1}}, kInfinity), 0);   // from the surface, away
    EXPECT_EQ(differingLanes(spheres, {{1, 0, -5}, {0, 0, 1}}, kInfinity), 0);  // grazing the side
    EXPECT_EQ(differingLanes(spheres, {{0, 0, 5}, {0, 0, 1}}, kInfinity), 0);   // behind
    EXPECT_EQ(differingLanes(spheres, {{0, 0, -5}, {0, 0, 1}}, Real(3.5)), 0);  // beyond tMax

    SphereBlock empty;  // no sphere set: no lane hits, whatever the ray
    for (const Ray& ray : {Ray{{0, 0, 0}, {0, 0, 1}}, Ray{{1, -2, 3}, normalize(Vec3{1, 1, 1})}})
        EXPECT_EQ(intersectBlock(empty, RayLanes(ray), kInfinity).lanes, 0u);
    EXPECT_EQ(empty.id[0], SphereBlock::kNoPrimitive);
}
