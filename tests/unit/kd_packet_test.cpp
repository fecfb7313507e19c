// Packet traversal (accel/kd_packet.cpp): every ray of a packet gets, bit for bit, the hit the
// single-ray traversal (accel/kd_single.cpp) gives it (the same primitive, t, u and v), which agrees with the naive
// list; and as a shadow ray (occludedPacket), each ending at its own distance, the answer and
// the counted work occluded() gives it. On camera and shadow rays of the thesis scenes, random
// triangles and the hard cases, through KD and BSP trees, in both precisions (the float build
// runs the same tests), on the SSE2, AVX2 and AVX-512 lanes (core/simd.h; skipped where the CPU
// lacks the level). And the single-ray traversal of each level gives SSE2's bits.
#include <cmath>
#include <cstring>
#include <memory>
#include <sstream>
#include <vector>

#include "accel/bsp.h"
#include "accel/kdtree.h"
#include "accel/naive.h"
#include "core/random.h"
#include "core/simd.h"
#include "packet_agreement.h"
#include "render/camera_rays.h"
#include "render/surface.h"
#include "scene/generate.h"
#include "scene/thesis_scenes.h"
#include "simd_lanes.h"
#include "test_util.h"

using namespace rt;
using namespace rt::test;

namespace rt {
void PrintTo(SimdLevel level, std::ostream* out) { *out << simdLevelName(level); }  // gtest's name for a failing level
}  // namespace rt

namespace {

std::vector<std::unique_ptr<Accelerator>> trees(const Primitives& prims,
                                                TriangleTest triangles = TriangleTest::MollerTrumbore) {
    std::vector<std::unique_ptr<Accelerator>> all;
    all.push_back(buildKdTree(prims, KdSettings{}, triangles));
    all.push_back(buildBspTree(prims, BspSettings{}, triangles));
    return all;
}

// A hit filter that asks what a scene's does (render/material_filter.h): a cut-out pattern over
// the hit's u and v, and, for some primitives, the side the ray comes from, the light's for a
// shadow ray. About half the hits pass.
struct CutOuts : HitFilter {
    bool accepts(const Ray& ray, const Hit& hit) const override {
        const Real pattern = hit.u * 13 + hit.v * 7;
        if (pattern - std::floor(pattern) < Real(0.4)) return false;
        return hit.prim % 5 != 0 || (ray.direction.z > 0) == ray.shadow;
    }
};

// Runs each test once per set of lanes the packet traversal can use.
class KdPacket : public test::SimdLanes {};

}  // namespace

INSTANTIATE_SIMD_LANES(KdPacket);

TEST_P(KdPacket, RandomTrianglesAgreeWithSingleRaysAndTheNaiveList) {
    const Scene scene = generateScene({2000, 0, Placement::Uniform, 21});
    const NaiveAccelerator naive(scene.primitives);
    const std::vector<Ray> rays = coneRays(600, 5);
    for (const auto& tree : trees(scene.primitives)) {
        for (int size : {kPacketSize, 5, 2, 1})
            EXPECT_EQ(packetDisagreements(*tree, rays, size, kInfinity, &naive), "");
        EXPECT_EQ(packetDisagreements(*tree, rays, kPacketSize, Real(1.2), &naive), "");  // a finite tMax
    }
}

TEST_P(KdPacket, SpheresCylindersAndConesAgreeWithSingleRays) {
    const Scene scene = generateScene({200, 200, Placement::Clustered, 22, 100, 100});
    const NaiveAccelerator naive(scene.primitives);
    for (const auto& tree : trees(scene.primitives))
        EXPECT_EQ(packetDisagreements(*tree, coneRays(600, 6), kPacketSize, kInfinity, &naive), "");
}

TEST_P(KdPacket, DisksAgreeWithSingleRays) {
    SceneRecipe recipe{100, 50, Placement::Clustered, 27};
    recipe.disks = 300;
    const Scene scene = generateScene(recipe);
    const NaiveAccelerator naive(scene.primitives);
    for (const auto& tree : trees(scene.primitives)) {
        EXPECT_EQ(packetDisagreements(*tree, coneRays(600, 7), kPacketSize, kInfinity, &naive), "");
        EXPECT_EQ(packetDisagreements(*tree, coneRays(600, 8), kPacketSize, Real(1.2), &naive), "");
    }
}

// Rays in the split planes, parallel to the axes and on the planes: packets with a zero direction
// component go one by one, and the others must still break ties as single rays do.
TEST_P(KdPacket, AxisAlignedRaysInSplitPlanesAgreeWithSingleRays) {
    const Scene scene = generateScene({300, 50, Placement::Clustered, 23});
    std::vector<Ray> rays;
    for (int p = 0; p < 400; ++p) {
        const Real x = Real(p % 20) / 10 - 1, y = Real(p / 20) / 10 - 1;
        for (int i = 0; i < kPacketSize; ++i) {
            const Vec3 d = p % 3 == 0 ? Vec3{0, 0, -1} : normalize(Vec3{Real(i) * Real(1e-3), Real(0.01), -1});
            rays.push_back({{x + Real(i % 4) / 40, y + Real(i / 4) / 40, 3}, d});
        }
    }
    for (const auto& tree : trees(scene.primitives))
        EXPECT_EQ(packetDisagreements(*tree, rays, kPacketSize, kInfinity), "");
}

TEST_P(KdPacket, CameraRaysOfSmallThesisScenesAgreeWithSingleRaysAndTheNaiveList) {
    for (const char* name : {"ships", "pyramid5"}) {
        const Scene scene = thesisScene(name);
        const NaiveAccelerator naive(scene.primitives);
        const auto tree = buildKdTree(scene.primitives, KdSettings{});
        EXPECT_EQ(packetDisagreements(*tree, cameraTiles(scene.camera, 80, 60), kPacketSize, kInfinity, &naive), "")
            << name;
    }
}

// Every camera ray of the larger thesis scenes at 320x240, against single rays only (the naive
// list would take minutes).
TEST_P(KdPacket, CameraRaysOfThesisScenesAgreeWithSingleRays) {
    for (const char* name : {"balls", "ships", "tree", "pyramid5"}) {
        const Scene scene = thesisScene(name);
        const auto tree = buildKdTree(scene.primitives, KdSettings{});
        EXPECT_EQ(packetDisagreements(*tree, cameraTiles(scene.camera, 320, 240), kPacketSize, kInfinity), "") << name;
    }
}

// Equally near hits (every triangle twice, and quads whose halves share an edge): the tie rule
// must be the single traversal's, the first found winning.
TEST_P(KdPacket, EquallyNearHitsGoToTheSamePrimitiveAsSingleRays) {
    Scene scene = generateScene({400, 0, Placement::Uniform, 24});
    Primitives& prims = scene.primitives;
    const std::uint32_t n = prims.count<Triangle>();
    for (std::uint32_t id = 0; id < n; ++id) prims.add<Triangle>(prims.all<Triangle>()[id], 0);
    for (int i = 0; i < 8; ++i) {  // quads facing the rays, split along a diagonal the rays cross
        const Real z = Real(i) / 4 - 1;
        prims.add<Triangle>({{-1, -1, z}, {1, -1, z}, {1, 1, z}}, 0);
        prims.add<Triangle>({{-1, -1, z}, {1, 1, z}, {-1, 1, z}}, 0);
    }
    std::vector<Ray> rays = coneRays(300, 7);
    for (int p = 0; p < 100; ++p)  // along the quads' diagonal x = y
        for (int i = 0; i < kPacketSize; ++i) {
            const Real s = Real(p) / 60 - Real(0.8) + Real(i) / 400;
            rays.push_back(
                {{s, s, 3}, normalize(Vec3{Real(1e-3) * Real(i % 3 + 1), Real(1e-3) * Real(i % 3 + 1), -1})});
        }
    for (const auto& tree : trees(prims)) EXPECT_EQ(packetDisagreements(*tree, rays, kPacketSize, kInfinity), "");
}

// The packet counts the work of each of its rays: the same nodes and tests as single rays, for
// the nearest hit and, stopping at the first blocking block or primitive, as shadow rays.
TEST_P(KdPacket, CountsTheSameWorkAsSingleRays) {
    const Scene scene = thesisScene("ships");
    const auto tree = buildKdTree(scene.primitives, KdSettings{});
    const std::vector<Ray> rays = cameraTiles(scene.camera, 80, 60);
    const auto [packet, single, packetShadows, singleShadows] = countedWork(*tree, rays);
    EXPECT_EQ(packet.traversalSteps, single.traversalSteps);
    EXPECT_EQ(packet.intersectionTests, single.intersectionTests);
    EXPECT_EQ(packetShadows.traversalSteps, singleShadows.traversalSteps);
    EXPECT_EQ(packetShadows.intersectionTests, singleShadows.intersectionTests);
}

// The shadow rays of the thesis scenes' pixels to their lights, as rt-render traces them, through
// KD and BSP trees: each ray's answer and the work counted as one by one.
TEST_P(KdPacket, ShadowRaysOfThesisScenesAgreeWithSingleRays) {
    for (const char* name : {"balls", "ships", "pyramid5"}) {
        const Scene scene = thesisScene(name);
        for (const auto& tree : trees(scene.primitives)) {
            std::vector<Real> ends;
            const std::vector<Ray> rays = shadowRaysOf(scene, *tree, 96, 72, ends);
            EXPECT_EQ(shadowDisagreements(*tree, rays, ends, kPacketSize), "") << name;
            EXPECT_EQ(shadowDisagreements(*tree, rays, ends, 3), "") << name;
        }
    }
}

// A tree with a hit filter (cut-outs, single-sided surfaces): each ray of a packet gets what the
// single ray gets, under the same filter, bit for bit, and the packet counts the same work, for
// the nearest hit and as a shadow ray; on every kind of primitive (triangles in blocks, the
// others one by one), with the watertight triangle test and without, and on the camera and
// shadow rays of a thesis scene.
TEST_P(KdPacket, HitFilterGivesSingleRaysBits) {
    SceneRecipe recipe{600, 60, Placement::Clustered, 28, 60, 60};
    recipe.disks = 60;
    const Scene scene = generateScene(recipe);
    const Scene ships = thesisScene("ships");
    const CutOuts filter;
    for (TriangleTest triangles : {TriangleTest::MollerTrumbore, TriangleTest::Watertight}) {
        const char* test = triangles == TriangleTest::Watertight ? "watertight" : "Moller-Trumbore";
        NaiveAccelerator naive(scene.primitives, triangles);
        naive.setHitFilter(&filter);
        for (const auto& tree : trees(scene.primitives, triangles)) {
            tree->setHitFilter(&filter);
            EXPECT_EQ(packetDisagreements(*tree, coneRays(400, 9), kPacketSize, kInfinity, &naive), "") << test;
            EXPECT_EQ(packetDisagreements(*tree, coneRays(400, 10), 5, Real(1.2)), "") << test;
        }
        for (const auto& tree : trees(ships.primitives, triangles)) {
            tree->setHitFilter(&filter);
            EXPECT_EQ(packetDisagreements(*tree, cameraTiles(ships.camera, 80, 60), kPacketSize, kInfinity), "")
                << test;
            std::vector<Real> ends;
            const std::vector<Ray> rays = shadowRaysOf(ships, *tree, 48, 36, ends);
            EXPECT_EQ(shadowDisagreements(*tree, rays, ends, kPacketSize), "") << test;
        }
    }
}

// Shadow rays that end nowhere (tMax 0, negative, tiny), graze the triangles' planes, start on
// them or have zero direction components (traced one by one), and a tree with a hit filter: the
// answers and counts of single rays.
TEST_P(KdPacket, DegenerateShadowRaysAgreeWithSingleRays) {
    Scene scene = generateScene({300, 20, Placement::Clustered, 25});
    for (int i = 0; i < 4; ++i) {  // a floor z = -1 split along its diagonal, and walls along x and y
        const Real w = Real(i);
        scene.primitives.add<Triangle>({{-2, -2, -1}, {2, -2, -1}, {2, 2, -1}}, 0);
        scene.primitives.add<Triangle>({{-2, -2, -1}, {2, 2, -1}, {-2, 2, -1}}, 0);
        scene.primitives.add<Triangle>({{w / 2, -2, -2}, {w / 2, 2, -2}, {w / 2, 0, 2}}, 0);
    }
    std::vector<Ray> rays;
    std::vector<Real> ends;
    const Real kinds[] = {0, -1, Real(1e-6), Real(0.5), 2, kInfinity};
    for (int p = 0; p < 300; ++p) {
        const Real s = Real(p) / 150 - 1;
        for (int i = 0; i < kPacketSize; ++i) {
            const Real o = s + Real(i) / 100;
            switch (p % 4) {
                case 0:
                    rays.push_back({{o, o, -1}, normalize(Vec3{1, Real(0.5), Real(1e-7) * Real(i)}), true});
                    break;
                case 1:
                    rays.push_back({{o, -o, -1}, normalize(Vec3{Real(0.3), Real(0.2), 1}), true});
                    break;
                case 2:
                    rays.push_back({{o, s, 3}, Vec3{0, 0, -1}, true});
                    break;
                default:
                    rays.push_back({{Real(0.5), o, s}, normalize(Vec3{Real(1e-9), 1, Real(i % 3) - 1}), true});
                    break;
            }
            ends.push_back(kinds[(std::size_t(p) + std::size_t(i)) % std::size(kinds)]);
        }
    }
    for (const auto& tree : trees(scene.primitives)) {
        EXPECT_EQ(shadowDisagreements(*tree, rays, ends, kPacketSize), "");
        struct Rejects : HitFilter {
            bool accepts(const Ray&, const Hit& hit) const override { return hit.prim % 2 == 0; }
        } filter;
        tree->setHitFilter(&filter);
        EXPECT_EQ(shadowDisagreements(*tree, rays, ends, kPacketSize), "");
        tree->setHitFilter(nullptr);
    }
}

// The single-ray traversal on this level's lanes against SSE2's, the baseline every x86-64 runs:
// the same nearest hit to the last bit, the same answer as a shadow ray, the same work counted.
// Through KD and BSP trees, with and without a hit filter, on triangles, spheres, cylinders and
// cones, rays in every direction and rays along the axes (zero direction components).
TEST_P(KdPacket, SingleRaysGiveTheBitsOfTheBaselineLanes) {
    const Scene scene = generateScene({600, 150, Placement::Clustered, 26, 50, 50});
    std::vector<Ray> rays = coneRays(200, 8);
    for (int p = 0; p < 200; ++p)
        rays.push_back({{Real(p % 20) / 10 - 1, Real(p / 20) / 10 - 1, 3}, p % 2 ? Vec3{0, 0, -1} : Vec3{0, -1, 0}});
    struct Answer {
        bool found, blocked;
        Hit hit;
    };
    const auto trace = [&](const Accelerator& tree, SimdLevel level, RayCounters& counters) {
        EXPECT_TRUE(setSimdLevel(level));
        std::vector<Answer> answers;
        for (const Ray& ray : rays) {
            Answer a{};
            a.found = tree.intersect(ray, kInfinity, a.hit, counters);
            a.blocked = tree.occluded(ray, a.found ? a.hit.t * Real(0.999) : Real(2), counters);
            answers.push_back(a);
        }
        return answers;
    };
    struct Rejects : HitFilter {
        bool accepts(const Ray&, const Hit& hit) const override { return hit.prim % 3 != 0; }
    } filter;
    for (const auto& tree : trees(scene.primitives))
        for (const HitFilter* f : {static_cast<const HitFilter*>(nullptr), static_cast<const HitFilter*>(&filter)}) {
            tree->setHitFilter(f);
            RayCounters baseline, lanes;
            const std::vector<Answer> expected = trace(*tree, SimdLevel::sse2, baseline);
            const std::vector<Answer> got = trace(*tree, GetParam(), lanes);
            int found = 0;
            for (std::size_t i = 0; i < rays.size(); ++i) {
                found += expected[i].found;
                EXPECT_TRUE(identical(got[i].found, got[i].hit, expected[i].found, expected[i].hit))
                    << tree->stats().name << " ray " << i << ": prim " << got[i].hit.prim << " t " << got[i].hit.t
                    << ", on SSE2 prim " << expected[i].hit.prim << " t " << expected[i].hit.t;
                EXPECT_EQ(got[i].blocked, expected[i].blocked) << tree->stats().name << " shadow ray " << i;
            }
            EXPECT_GT(found, 50) << tree->stats().name;  // the rays do meet the scene
            EXPECT_EQ(lanes.traversalSteps, baseline.traversalSteps) << tree->stats().name;
            EXPECT_EQ(lanes.intersectionTests, baseline.intersectionTests) << tree->stats().name;
        }
}
