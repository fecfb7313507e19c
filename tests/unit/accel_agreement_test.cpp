// Property tests: every tree returns the naive list's answers (issue 4, "Correctness").
// Each scene is shot with 100,000 rays of several kinds; for each ray the nearest hit
// must be the same primitive, or at a distance equal within a relative 1e-4 (an equally
// near hit), and the shadow query must give the same answer.
#include <array>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

#include "accel/bsp.h"
#include "accel/bvh.h"
#include "accel/kdtree.h"
#include "accel/naive.h"
#include "core/random.h"
#include "scene/generate.h"
#include "test_util.h"

using namespace rt;

namespace {

constexpr int kRays = 100000;

// Reproducible rays (core/random.h).
struct TestRandom {
    SplitMix64 rng;
    std::uint64_t next() { return rng.next(); }
    Real uniform(Real lo, Real hi) { return lo + (hi - lo) * Real(rng.uniform()); }
    Vec3 direction() {
        for (;;) {
            const Vec3 d{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
            if (dot(d, d) > Real(0.01) && dot(d, d) <= 1) return normalize(d);
        }
    }
    // A coordinate that is often exactly a likely split plane.
    Real gridOrUniform() {
        static constexpr Real kGrid[] = {-1, -0.5, -0.25, 0, 0.25, 0.5, 1};
        return next() % 2 ? kGrid[next() % 7] : uniform(-1.2, 1.2);
    }
};

// A point on primitive `id`: rays starting on a surface.
Vec3 pointOn(const Primitives& prims, std::uint32_t id, TestRandom& random) {
    const Real u = random.uniform(0, 1), v = random.uniform(0, 1);
    return prims.visit(id, [&](const auto& p) { return p.surfacePoint(u, v); });
}

Ray makeRay(const Primitives& prims, int i, TestRandom& random) {
    switch (i % 4) {
        case 0:
            return {{random.uniform(-1.5, 1.5), random.uniform(-1.5, 1.5), random.uniform(-1.5, 1.5)},
                    random.direction()};
        case 1: {  // parallel to an axis, often in a plane where trees like to split
            Vec3 d{0, 0, 0};
            d[int(random.next() % 3)] = random.next() % 2 ? 1 : -1;
            return {{random.gridOrUniform(), random.gridOrUniform(), random.gridOrUniform()}, d};
        }
        case 2:
            return {pointOn(prims, std::uint32_t(random.next() % prims.size()), random), random.direction()};
        default:
            return {Vec3{0, 0, 3} + Vec3{random.uniform(-1, 1), random.uniform(-1, 1), 0},
                    normalize(Vec3{random.uniform(-0.4f, 0.4f), random.uniform(-0.4f, 0.4f), -1})};
    }
}

bool sameNearest(bool naiveFound, const Hit& naive, bool treeFound, const Hit& tree) {
    if (naiveFound != treeFound) return false;
    if (!naiveFound || naive.prim == tree.prim) return true;
    return std::abs(naive.t - tree.t) <= Real(1e-4) * std::max(std::abs(naive.t), std::abs(tree.t));
}

std::vector<std::unique_ptr<Accelerator>> allTrees(const Primitives& prims) {
    std::vector<std::unique_ptr<Accelerator>> trees;
    trees.push_back(buildBspTree(prims, BspSettings{}));
    BspSettings roundRobin;
    roundRobin.roundRobin = true;
    roundRobin.minPrimitives = 1;
    trees.push_back(buildBspTree(prims, roundRobin));
    for (KdSplitMethod method : {KdSplitMethod::Sweep, KdSplitMethod::Sort, KdSplitMethod::Sample}) {
        KdSettings kd;
        kd.splitMethod = method;
        trees.push_back(buildKdTree(prims, kd));
    }
    KdSettings binned;  // the binning of the large nodes, here in every node of 16 primitives or more
    binned.binningMinimum = 16;
    trees.push_back(buildKdTree(prims, binned));
    trees.push_back(buildBvh(prims, BvhSettings{}));
    BvhSettings singles;  // a leaf per primitive: the most boxes between a ray and its hit
    singles.maxLeafPrimitives = 1;
    trees.push_back(buildBvh(prims, singles));
    return trees;
}

// Shoots `rays` rays at every tree and at the naive list; returns a description of the
// first disagreements, empty if there is none.
std::string disagreements(const Primitives& prims, int rays, std::uint64_t seed) {
    const NaiveAccelerator naive(prims);
    const auto trees = allTrees(prims);
    std::vector<RayCounters> counters(trees.size());
    RayCounters naiveCounters;
    TestRandom random{SplitMix64(seed)};
    std::ostringstream out;
    int reported = 0;
    for (int i = 0; i < rays && reported < 5; ++i) {
        const Ray ray = makeRay(prims, i, random);
        Hit expected;
        const bool found = naive.intersect(ray, kInfinity, expected, naiveCounters);
        // Shadow distances well away from the nearest hit, where the answer is clear-cut.
        const Real shadowT = !found || i % 3 == 0 ? kInfinity : expected.t * (i % 3 == 1 ? Real(0.5) : Real(1.5));
        const bool shadowed = found && expected.t < shadowT;  // what the naive list's occluded() answers
        for (std::size_t k = 0; k < trees.size(); ++k) {
            Hit hit;
            const bool treeFound = trees[k]->intersect(ray, kInfinity, hit, counters[k]);
            const bool treeShadowed = trees[k]->occluded(ray, shadowT, counters[k]);
            if (sameNearest(found, expected, treeFound, hit) && shadowed == treeShadowed) continue;
            out << trees[k]->stats().name << " ray " << i << " o=" << ray.origin << " d=" << ray.direction << ": naive "
                << found << " prim " << expected.prim << " t " << expected.t << " shadow " << shadowed << "; tree "
                << treeFound << " prim " << hit.prim << " t " << hit.t << " shadow " << treeShadowed << '\n';
            ++reported;
        }
    }
    // The trees must actually save work on these scenes, or the test proves little.
    for (std::size_t k = 0; k < trees.size() && reported == 0; ++k) {
        if (counters[k].intersectionTests * 4 > naiveCounters.intersectionTests)
            out << trees[k]->stats().name << " did not save intersection tests\n";
    }
    return out.str();
}

// Triangles in the planes the trees split at, huge and tiny primitives, duplicates, and a
// sphere enclosing everything (rays from inside it).
Primitives hardCases() {
    Primitives prims = generateScene({150, 50, Placement::Clustered, 7}).primitives;
    TestRandom random{SplitMix64(99)};
    for (int i = 0; i < 60; ++i) {  // axis-aligned triangles lying in x = 0, y = 0.5, z = -0.25, ...
        const int axis = i % 3;
        const Real plane = std::array<Real, 4>{0, Real(0.5), Real(-0.25), Real(0.25)}[i % 4];
        Vec3 p[3];
        for (Vec3& v : p) {
            v = {random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)};
            v[axis] = plane;
        }
        prims.add<Triangle>({p[0], p[1], p[2]}, 0);
    }
    prims.add<Triangle>({{-5, -5, -0.9f}, {5, -5, -0.9f}, {0, 5, 0.9f}}, 0);  // huge, slanted
    prims.add<Triangle>({{-4, 0.3f, -4}, {4, 0.3f, -4}, {0, 0.3f, 4}}, 0);    // huge, in a plane
    for (int i = 0; i < 40; ++i) {                                            // tiny
        const Vec3 c{random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)};
        prims.add<Triangle>({c, c + Vec3{Real(1e-4), 0, 0}, c + Vec3{0, Real(1e-4), Real(1e-5)}}, 0);
        prims.add<Sphere>({c, Real(1e-4)}, 0);
    }
    const std::uint32_t n = prims.count<Triangle>();
    for (std::uint32_t id = 0; id < n; id += 7) prims.add<Triangle>(prims.all<Triangle>()[id], 0);  // coincident
    prims.add<Sphere>({{0.2f, 0.1f, 0}, Real(0.3)}, 0);
    prims.add<Sphere>({{0.2f, 0.1f, 0}, Real(0.3)}, 0);
    prims.add<Sphere>({{0, 0, 0}, Real(4)}, 0);  // everything is inside
    // Axis-aligned in split planes, coincident, and one around everything.
    for (int i = 0; i < 3; ++i) {
        Vec3 a{0, Real(0.5), Real(-0.25)}, b = a;
        b[i] += 1;
        prims.add<Cylinder>({{a, b, Real(0.25), Real(0.25)}}, 0);
        prims.add<Cylinder>({{a, b, Real(0.25), Real(0.25)}}, 0);
        prims.add<Cone>({{b, a, Real(0.5), 0}}, 0);
    }
    prims.add<Cone>({{{0, 0, -5}, {0, 0, 5}, Real(5), Real(3)}}, 0);
    // Disks in split planes (their bounds flat), coincident, tiny, and one across everything.
    for (int i = 0; i < 3; ++i) {
        Vec3 normal{0, 0, 0};
        normal[i] = 1;
        const Disk d{{Real(0.25) * Real(i), Real(0.5), Real(-0.25)}, normal, Real(0.3)};
        prims.add<Disk>(d, 0);
        prims.add<Disk>(d, 0);
        prims.add<Disk>({d.center, normal, Real(1e-4)}, 0);
    }
    prims.add<Disk>({{0, 0, 0}, normalize(Vec3{1, 1, 1}), Real(6)}, 0);
    return prims;
}

}  // namespace

TEST(AccelAgreement, UniformTrianglesAndSpheres) {
    const Scene scene = generateScene({240, 80, Placement::Uniform, 1});
    EXPECT_EQ(disagreements(scene.primitives, kRays, 11), "");
}

TEST(AccelAgreement, ClusteredTrianglesAndSpheres) {
    const Scene scene = generateScene({240, 80, Placement::Clustered, 2});
    EXPECT_EQ(disagreements(scene.primitives, kRays, 12), "");
}

TEST(AccelAgreement, UniformWithCylindersAndCones) {
    const Scene scene = generateScene({120, 40, Placement::Uniform, 3, 60, 60});
    EXPECT_EQ(disagreements(scene.primitives, kRays, 14), "");
}

TEST(AccelAgreement, ClusteredWithCylindersAndCones) {
    const Scene scene = generateScene({120, 40, Placement::Clustered, 4, 60, 60});
    EXPECT_EQ(disagreements(scene.primitives, kRays, 15), "");
}

// Disks reach the trees through the kinds list and their block alone (geometry/disk.h).
TEST(AccelAgreement, ClusteredDisksAmongTrianglesAndSpheres) {
    SceneRecipe recipe{60, 20, Placement::Clustered, 5};
    recipe.disks = 240;
    const Scene scene = generateScene(recipe);
    ASSERT_GT(scene.primitives.count<Disk>(), 200u);
    EXPECT_EQ(disagreements(scene.primitives, kRays, 16), "");
}

TEST(AccelAgreement, PlanesHugeTinyAndCoincidentPrimitives) { EXPECT_EQ(disagreements(hardCases(), kRays, 13), ""); }
