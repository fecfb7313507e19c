// Packet traversal of the wide BVH (accel/bvh_packet.cpp): every ray of a packet gets, bit for bit,
// the hit the single-ray traversal (accel/bvh_traversal.cpp) gives it (the same primitive, t, u and
// v), and as a shadow ray the answer occluded() gives it: on random and coherent rays, camera and
// shadow rays of the thesis scenes, rays along the axes, every primitive kind, huge and tiny
// primitives, exactly equal hits in different leaves, with the watertight triangle test and with a hit filter, on the
// SSE2, AVX2 and AVX-512 lanes (skipped where the CPU lacks the level), in both precisions (the
// float build runs the same tests). The packet counts its own work: nodes and tests of its order.
#include <memory>
#include <random>
#include <vector>

#include "accel/bvh.h"
#include "accel/naive.h"
#include "core/random.h"
#include "packet_agreement.h"
#include "scene/generate.h"
#include "scene/thesis_scenes.h"
#include "simd_lanes.h"
#include "test_util.h"

using namespace rt;
using namespace rt::test;

namespace {

// The BVH with either triangle test.
std::vector<std::unique_ptr<Accelerator>> bvhs(const Primitives& prims) {
    std::vector<std::unique_ptr<Accelerator>> all;
    all.push_back(buildBvh(prims, BvhSettings{}));
    all.push_back(buildBvh(prims, BvhSettings{}, TriangleTest::Watertight));
    return all;
}

// packetDisagreements for the BVH: its packets count their own work.
std::string disagreements(const Accelerator& bvh, const std::vector<Ray>& rays, int packetSize, Real tMax,
                          const Accelerator* naive = nullptr) {
    return packetDisagreements(bvh, rays, packetSize, tMax, naive, Counts::Own);
}

// Rejects every third primitive: cut-outs, as a material's alpha makes them.
struct RejectsEveryThird : HitFilter {
    bool accepts(const Ray&, const Hit& hit) const override { return hit.prim % 3 != 0; }
};

// Runs each test once per set of lanes the packet traversal can use.
class BvhPacket : public SimdLanes {};

}  // namespace

INSTANTIATE_SIMD_LANES(BvhPacket);

TEST_P(BvhPacket, RandomTrianglesAgreeWithSingleRaysAndTheNaiveList) {
    const Scene scene = generateScene({2000, 0, Placement::Uniform, 21});
    const NaiveAccelerator naive(scene.primitives);
    const std::vector<Ray> rays = coneRays(200, 5);
    for (const auto& bvh : bvhs(scene.primitives)) {
        for (int size : {kPacketSize, 3}) EXPECT_EQ(disagreements(*bvh, rays, size, kInfinity, &naive), "") << size;
        EXPECT_EQ(disagreements(*bvh, rays, kPacketSize, Real(1.2), &naive), "");  // a finite tMax
    }
}

// Spheres, cylinders, cones and disks beside triangles (the kinds with blocks and the others), with
// a finite tMax too.
TEST_P(BvhPacket, EveryPrimitiveKindAgreesWithSingleRays) {
    SceneRecipe recipe{200, 200, Placement::Clustered, 22, 100, 100};
    recipe.disks = 200;
    const Scene scene = generateScene(recipe);
    const NaiveAccelerator naive(scene.primitives);
    const std::vector<Ray> rays = coneRays(300, 6);
    for (const auto& bvh : bvhs(scene.primitives))
        for (Real tMax : {kInfinity, Real(1.2)}) EXPECT_EQ(disagreements(*bvh, rays, kPacketSize, tMax, &naive), "");
}

// Packets along each axis both ways, and with one or two direction components zero: infinite
// reciprocals, 0 * inf = NaN where an origin lies on a plane, in the packet's slab test as in the
// single one.
TEST_P(BvhPacket, RaysAlongTheAxesAgreeWithSingleRays) {
    const Scene scene = generateScene({300, 50, Placement::Clustered, 23});
    std::vector<Ray> rays;
    for (int axis = 0; axis < 3; ++axis)
        for (int tile = 0; tile < 120; ++tile) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            for (int i = 0; i < kPacketSize; ++i) {
                Vec3 origin, direction;
                origin[axis] = tile % 2 ? -3 : 3;
                origin[u] = Real(tile % 12) / 6 - 1 + Real(i % 4) / 32;
                origin[v] = Real(tile / 12) / 5 - 1 + Real(i / 4) / 32;
                direction[axis] = tile % 2 ? 1 : -1;
                if (tile % 3 == 1) direction[u] = Real(i) / 64;  // one component zero
                rays.push_back({origin, normalize(direction)});
            }
        }
    const NaiveAccelerator naive(scene.primitives);
    for (const auto& bvh : bvhs(scene.primitives))
        EXPECT_EQ(disagreements(*bvh, rays, kPacketSize, kInfinity, &naive), "");
}

// Camera rays in 4x2 tiles and the shadow rays of their hits to the lights, as rt-render traces
// them.
TEST_P(BvhPacket, CameraAndShadowRaysOfThesisScenesAgreeWithSingleRays) {
    for (const char* name : {"balls", "ships", "pyramid5"}) {
        const Scene scene = thesisScene(name);
        for (const auto& bvh : bvhs(scene.primitives)) {
            EXPECT_EQ(disagreements(*bvh, cameraTiles(scene.camera, 96, 72), kPacketSize, kInfinity), "") << name;
            std::vector<Real> ends;
            const std::vector<Ray> rays = shadowRaysOf(scene, *bvh, 64, 48, ends);
            EXPECT_EQ(shadowDisagreements(*bvh, rays, ends, kPacketSize, Counts::Own), "") << name;
        }
    }
}

// Many exactly equal hits in different leaves, which the packet meets in another order than a ray
// alone: overlapping right triangles in a few planes z = const, their legs powers of two and every
// coordinate a multiple of 1/8, hit by rays of such directions, so that every triangle under a
// point reports exactly the same t; leaves of many shapes, so the packet's first ray and the others
// order them differently.
TEST_P(BvhPacket, ExactTiesInDifferentLeavesGoToTheSamePrimitiveAsSingleRays) {
    Primitives prims;
    SplitMix64 rng(30);
    const auto grid = [&](int steps) { return Real(int(rng.next() % std::uint64_t(steps))) / 8; };
    for (int i = 0; i < 600; ++i) {
        const Real x = grid(16) - 1, y = grid(16) - 1, z = grid(4) * 2;
        const Real legX = Real(1) / Real(1 << (rng.next() % 3)), legY = Real(1) / Real(1 << (rng.next() % 3));
        prims.add<Triangle>({{x, y, z}, {x + legX, y, z}, {x, y + legY, z}}, 0);
    }
    std::vector<Ray> rays;
    for (int p = 0; p < 400; ++p) {
        const Real x = grid(16) - 1, y = grid(16) - 1;
        for (int i = 0; i < kPacketSize; ++i)
            rays.push_back({{x + Real(i % 4) / 8, y + Real(i / 4) / 8, 3}, {Real(i % 3) / 16, Real(p % 4) / 16, -1}});
    }
    const auto bvh = buildBvh(prims, BvhSettings{});
    EXPECT_EQ(disagreements(*bvh, rays, kPacketSize, kInfinity), "");
}

// Tiny triangles and spheres at one point seen from a unit away (the slack's case), and huge
// triangles across the whole scene around small ones.
TEST_P(BvhPacket, HugeAndTinyPrimitivesAgreeWithSingleRays) {
    Scene scene = generateScene({300, 30, Placement::Clustered, 28});
    Primitives& prims = scene.primitives;
    std::mt19937 gen(4);
    std::uniform_real_distribution<Real> tiny(Real(-1e-6), Real(1e-6));
    const Vec3 p{Real(0.3), Real(0.3), Real(0.3)};
    for (int i = 0; i < 500; ++i) {
        prims.add<Triangle>({p, p + Vec3{tiny(gen), tiny(gen), tiny(gen)}, p + Vec3{tiny(gen), tiny(gen), tiny(gen)}},
                            0);
        if (i % 10 == 0) prims.add<Sphere>({p, Real(1e-6)}, 0);
    }
    prims.add<Triangle>({{-1e6, -1e6, Real(-0.5)}, {1e6, -1e6, Real(0.5)}, {0, 1e6, 0}}, 0);
    prims.add<Sphere>({{0, 0, -1e5}, Real(1e5 - 2)}, 0);
    std::vector<Ray> rays = coneRays(200, 9);
    for (int q = 0; q < 50; ++q)  // at the tiny cluster from a unit away
        for (int i = 0; i < kPacketSize; ++i)
            rays.push_back(
                {p + Vec3{1, Real(q) * Real(1e-3), Real(i) * Real(1e-7)}, Vec3{-1, Real(i) * Real(1e-7), 0}});
    for (const auto& bvh : bvhs(prims)) EXPECT_EQ(disagreements(*bvh, rays, kPacketSize, kInfinity), "");
}

// With a hit filter (cut-outs) the leaves skip what it rejects, for the nearest hit and shadows,
// as the single rays do.
TEST_P(BvhPacket, AHitFilterIsHonouredAsBySingleRays) {
    SceneRecipe recipe{600, 100, Placement::Clustered, 29, 30, 30};
    recipe.disks = 50;
    const Scene scene = generateScene(recipe);
    const RejectsEveryThird filter;
    for (const auto& bvh : bvhs(scene.primitives)) {
        bvh->setHitFilter(&filter);
        EXPECT_EQ(disagreements(*bvh, coneRays(300, 10), kPacketSize, kInfinity), "");
        EXPECT_EQ(disagreements(*bvh, cameraTiles(thesisScene("ships").camera, 32, 24), kPacketSize, kInfinity), "");
    }
}

// The packet counts sensibly: every ray's nodes and tests of its walk, which, in the packet's
// order, are about what the single rays count (more where a ray waits in a node its own order
// would have culled, fewer where a blocked shadow ray leaves early).
TEST_P(BvhPacket, CountsAboutTheWorkOfSingleRays) {
    const Scene scene = thesisScene("ships");
    const auto bvh = buildBvh(scene.primitives, BvhSettings{});
    const std::vector<Ray> rays = cameraTiles(scene.camera, 80, 60);
    const auto [packet, single, packetShadows, singleShadows] = countedWork(*bvh, rays);
    const auto near = [](std::uint64_t got, std::uint64_t expected) {
        return double(got) >= 0.5 * double(expected) && double(got) <= 1.5 * double(expected);
    };
    EXPECT_PRED2(near, packet.traversalSteps, single.traversalSteps);
    EXPECT_PRED2(near, packet.intersectionTests, single.intersectionTests);
    EXPECT_PRED2(near, packetShadows.traversalSteps, singleShadows.traversalSteps);
    EXPECT_PRED2(near, packetShadows.intersectionTests, singleShadows.intersectionTests);
}
