// The watertight triangle test (geometry/watertight_triangle.h, AccelSettings::triangles): its
// blocks against its scalar test, bit for bit; the exact signs it falls back on; and, in every
// structure and on every level's lanes, no ray slipping through the shared edges and vertices of
// closed meshes, where Moller-Trumbore lets some through.
#include "geometry/watertight_triangle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "accel/build.h"
#include "core/random.h"
#include "simd_lanes.h"
#include "test_util.h"

using namespace rt;

namespace {

// Tests `tris` (kSimdWidth of them) as one block and one by one; returns the lanes that differ.
int differingWatertightLanes(const Triangle* tris, const Ray& ray, Real tMax) {
    VertexBlock block;
    for (int lane = 0; lane < kSimdWidth; ++lane) block.set(lane, tris[lane], std::uint32_t(lane));
    const ShearedRay sheared(ray);
    const BlockHits hits = intersectBlock(block, ShearedRayLanes(sheared), tMax);
    int differing = 0;
    for (int lane = 0; lane < kSimdWidth; ++lane) {
        Real t = 0, u = 0, v = 0;
        const bool hit = intersectWatertight(tris[lane], sheared, tMax, t, u, v);
        const bool laneHit = (hits.lanes >> lane) & 1u;
        differing += hit != laneHit || (hit && (t != hits.t[lane] || u != hits.u[lane] || v != hits.v[lane]));
    }
    return differing;
}

// A closed triangle mesh: vertices shared by index, so a shared vertex is the same value in each
// of its triangles.
struct Mesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    Vec3 centre;

    Primitives primitives() const {
        Primitives prims;
        for (const auto& t : triangles) prims.add(Triangle{vertices[t[0]], vertices[t[1]], vertices[t[2]]}, 0);
        return prims;
    }
    // Each edge once, as its two vertices' indices, lower first.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges() const {
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> seen;
        for (const auto& t : triangles)
            for (int k = 0; k < 3; ++k) ++seen[std::minmax(t[k], t[(k + 1) % 3])];
        std::vector<std::pair<std::uint32_t, std::uint32_t>> all;
        for (const auto& [edge, count] : seen) all.push_back(edge);
        return all;
    }
};

// The unit cube's surface, an n x n grid of quads per face, each cut along the same diagonal (so
// a vertex inside a face has six triangles), turned and moved to coordinates no float or double
// holds exactly. `turned` false: axis-aligned, moved only.
Mesh gridCube(int n, bool turned) {
    Mesh mesh;
    std::map<std::array<int, 3>, std::uint32_t> index;  // grid point -> vertex
    const Real a = turned ? Real(0.61) : 0, b = turned ? Real(0.37) : 0;
    const Vec3 offset{Real(0.3), Real(-0.2), Real(0.1)};
    const auto vertex = [&](std::array<int, 3> g) {
        const auto [it, added] = index.try_emplace(g, std::uint32_t(mesh.vertices.size()));
        if (added) {
            const Vec3 q{Real(g[0]) / Real(n) - Real(0.5), Real(g[1]) / Real(n) - Real(0.5),
                         Real(g[2]) / Real(n) - Real(0.5)};
            // Turned by a about z, then by b about x.
            const Vec3 r{q.x * std::cos(a) - q.y * std::sin(a), q.x * std::sin(a) + q.y * std::cos(a), q.z};
            mesh.vertices.push_back(
                offset + Vec3{r.x, r.y * std::cos(b) - r.z * std::sin(b), r.y * std::sin(b) + r.z * std::cos(b)});
        }
        return it->second;
    };
    for (int axis = 0; axis < 3; ++axis)
        for (int side : {0, n})
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const auto at = [&](int di, int dj) {
                        std::array<int, 3> g{};
                        g[axis] = side;
                        g[(axis + 1) % 3] = i + di;
                        g[(axis + 2) % 3] = j + dj;
                        return vertex(g);
                    };
                    mesh.triangles.push_back({at(0, 0), at(1, 0), at(1, 1)});
                    mesh.triangles.push_back({at(0, 0), at(1, 1), at(0, 1)});
                }
    mesh.centre = offset;
    return mesh;
}

// An icosahedron subdivided `levels` times onto a sphere of radius 1.3 about (0.2, 0.1, -0.3):
// vertices of five and six triangles, edges in every direction.
Mesh icosphere(int levels) {
    Mesh mesh;
    const Real p = (1 + std::sqrt(Real(5))) / 2;
    mesh.vertices = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
                     {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
    mesh.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (Vec3& v : mesh.vertices) v = normalize(v);
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
        const auto midpoint = [&](std::uint32_t i, std::uint32_t j) {
            const auto [it, added] = middle.try_emplace(std::minmax(i, j), std::uint32_t(mesh.vertices.size()));
            if (added) mesh.vertices.push_back(normalize(mesh.vertices[i] + mesh.vertices[j]));
            return it->second;
        };
        std::vector<std::array<std::uint32_t, 3>> finer;
        for (const auto& [i, j, k] : mesh.triangles) {
            const std::uint32_t ij = midpoint(i, j), jk = midpoint(j, k), ki = midpoint(k, i);
            finer.insert(finer.end(), {{i, ij, ki}, {ij, j, jk}, {ki, jk, k}, {ij, jk, ki}});
        }
        mesh.triangles = std::move(finer);
    }
    mesh.centre = {Real(0.2), Real(0.1), Real(-0.3)};
    for (Vec3& v : mesh.vertices) v = mesh.centre + v * Real(1.3);
    return mesh;
}

// A ray that must meet the mesh's surface at distance `entry` (unit directions): a hit before
// entry * (1 + 1e-3) or none means that it slipped through.
struct AimedRay {
    Ray ray;
    Real entry;
};

// Rays at the points `targets` on the surface of a convex mesh: from outside through the point
// to the centre, from the centre out through it, and, for the points in `alongAxes`, along the
// axis nearest to the inward direction (through a vertex, an axis-parallel ray).
std::vector<AimedRay> raysAt(const Mesh& mesh, const std::vector<Vec3>& targets, const std::vector<Vec3>& alongAxes) {
    std::vector<AimedRay> rays;
    for (const Vec3& target : targets) {
        const Vec3 out = target - mesh.centre;
        const Vec3 origin = mesh.centre + out * 3;
        rays.push_back({{origin, normalize(target - origin)}, length(target - origin)});
        rays.push_back({{mesh.centre, normalize(out)}, length(out)});
    }
    for (const Vec3& target : alongAxes) {
        const Vec3 out = target - mesh.centre;
        int axis = std::abs(out.y) > std::abs(out.x) ? 1 : 0;
        if (std::abs(out.z) > std::abs(out[axis])) axis = 2;
        Vec3 direction{0, 0, 0};
        direction[axis] = out[axis] > 0 ? -1 : 1;
        Vec3 origin = target;
        origin[axis] -= direction[axis] * 4;  // only the axis's coordinate moves: the ray runs through target
        rays.push_back({{origin, direction}, 4});
    }
    return rays;
}

// The shared edges (at three points each) and vertices of a mesh as targets; every vertex also
// along an axis, for a cube only those inside a face (`insideFace`: six triangles meet there).
std::vector<AimedRay> edgeAndVertexRays(const Mesh& mesh, bool onlyInsideFaceAlongAxes) {
    std::vector<Vec3> targets, alongAxes;
    for (const auto& [i, j] : mesh.edges())
        for (Real s : {Real(0.5), Real(1) / Real(3), Real(0.71)})
            targets.push_back(mesh.vertices[i] + (mesh.vertices[j] - mesh.vertices[i]) * s);
    for (const Vec3& v : mesh.vertices) {
        targets.push_back(v);
        const Vec3 out = v - mesh.centre;
        // On a cube face's inside the vertex lies well within the face: no coordinate near the
        // face's edges, where the axis ray could only graze the surface.
        const Real largest = std::max({std::abs(out.x), std::abs(out.y), std::abs(out.z)});
        if (!onlyInsideFaceAlongAxes || largest < length(out) * Real(0.9)) alongAxes.push_back(v);
    }
    return raysAt(mesh, targets, alongAxes);
}

bool slipped(bool found, Real t, const AimedRay& aimed) { return !found || !(t < aimed.entry * Real(1.001)); }

// How many of `rays` each query lets slip through: nearest hit, any hit, and both as packets of
// eight in turn.
struct Slips {
    int nearest = 0, any = 0, nearestPackets = 0, anyPackets = 0;
    int total() const { return nearest + any + nearestPackets + anyPackets; }
};

Slips slipsThrough(const Accelerator& accel, const std::vector<AimedRay>& rays) {
    Slips slips;
    RayCounters counters;
    for (const AimedRay& aimed : rays) {
        Hit hit;
        const bool found = accel.intersect(aimed.ray, kInfinity, hit, counters);
        slips.nearest += slipped(found, hit.t, aimed);
        slips.any += !accel.occluded(aimed.ray, aimed.entry * Real(1.001), counters);
    }
    for (std::size_t first = 0; first < rays.size(); first += kPacketSize) {
        const int count = int(std::min<std::size_t>(kPacketSize, rays.size() - first));
        Ray packet[kPacketSize];
        Real ends[kPacketSize];
        for (int i = 0; i < count; ++i) {
            packet[i] = rays[first + std::size_t(i)].ray;
            ends[i] = rays[first + std::size_t(i)].entry * Real(1.001);
        }
        Hit hits[kPacketSize];
        bool found[kPacketSize], blocked[kPacketSize];
        accel.intersectPacket(packet, count, kInfinity, hits, found, counters);
        accel.occludedPacket(packet, count, ends, blocked, counters);
        for (int i = 0; i < count; ++i) {
            slips.nearestPackets += slipped(found[i], hits[i].t, rays[first + std::size_t(i)]);
            slips.anyPackets += !blocked[i];
        }
    }
    return slips;
}

struct ClosedMesh {
    const char* name;
    Mesh mesh;
    bool onlyInsideFaceAlongAxes;
};

std::vector<ClosedMesh> closedMeshes() {
    return {{"turned cube", gridCube(4, true), true},
            {"axis-aligned cube", gridCube(3, false), true},
            {"icosphere", icosphere(1), false}};
}

// Rays of `rays` whose nearest hit in `accel` is neither the naive list's primitive nor as near.
int differingFromNaive(const Accelerator& naive, const Accelerator& accel, const std::vector<AimedRay>& rays) {
    int differing = 0;
    RayCounters counters;
    for (const AimedRay& aimed : rays) {
        Hit a, b;
        const bool foundA = naive.intersect(aimed.ray, kInfinity, a, counters);
        const bool foundB = accel.intersect(aimed.ray, kInfinity, b, counters);
        const bool asNear = std::abs(a.t - b.t) <= Real(1e-4) * std::max(std::abs(a.t), std::abs(b.t));
        differing += foundA != foundB || (foundA && a.prim != b.prim && !asNear);
    }
    return differing;
}

class WatertightMeshes : public test::SimdLanes {};
INSTANTIATE_SIMD_LANES(WatertightMeshes);

constexpr AccelKind kKinds[] = {AccelKind::Naive, AccelKind::Bsp, AccelKind::Kd, AccelKind::Bvh};

AccelSettings settingsFor(AccelKind kind, TriangleTest triangles) {
    AccelSettings settings;
    settings.kind = kind;
    settings.triangles = triangles;
    settings.bsp.minPrimitives = 2;  // small leaves: the shared edges between leaves too
    return settings;
}

}  // namespace

TEST(WatertightTriangle, BlockLanesHaveTheScalarTestsBits) {
    SplitMix64 rng(21);
    const auto point = [&] {
        return Vec3{Real(2 * rng.uniform() - 1), Real(2 * rng.uniform() - 1), Real(2 * rng.uniform() - 1)};
    };
    int hits = 0, differing = 0;
    for (int i = 0; i < 20000; ++i) {
        Triangle tris[kSimdWidth];
        for (Triangle& tri : tris) tri = {point(), point(), point()};
        // Every other ray through a vertex: its edge functions are zero, the exact fallback's case.
        const Vec3 origin = point();
        const Ray ray{origin, i % 2 ? normalize(point()) : tris[0].p1 - origin};
        const Real tMax = i % 3 ? kInfinity : Real(0.5);
        differing += differingWatertightLanes(tris, ray, tMax);
        Real t, u, v;
        for (const Triangle& tri : tris) hits += intersectWatertight(tri, ShearedRay(ray), tMax, t, u, v);
    }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(hits, 5000);  // enough hits to compare, through vertices among them
}

TEST(WatertightTriangle, UnusedLanesAndEdgeOnTrianglesNeverHit) {
    VertexBlock empty;
    const Ray down{{0, 0, 1}, {0, 0, -1}};
    EXPECT_EQ(intersectBlock(empty, ShearedRayLanes(ShearedRay(down)), kInfinity).lanes, 0u);
    Real t, u, v;
    // In the plane x = 0 that the ray runs in: no area seen along it.
    EXPECT_FALSE(intersectWatertight({{0, -1, -1}, {0, 1, -1}, {0, 0, 1}}, ShearedRay(down), kInfinity, t, u, v));
    // Barycentrics as Moller-Trumbore's: u the weight of p1, v of p2.
    ASSERT_TRUE(intersectWatertight({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                    ShearedRay({{Real(0.25), Real(0.5), 2}, {0, 0, -1}}), kInfinity, t, u, v));
    EXPECT_NEAR(t, 2, kTol);
    EXPECT_NEAR(u, 0.25, kTol);
    EXPECT_NEAR(v, 0.5, kTol);
}

// Where the two products round to the same value, their difference computed plainly is zero;
// the fallback gives the exact difference's sign.
TEST(WatertightTriangle, ExactDifferenceOfProductsKeepsTheSign) {
    const Real e = std::numeric_limits<Real>::epsilon();
    const Real a = 1 + e, b = 1 - e;  // a * b = 1 - e^2, which rounds to 1
    EXPECT_EQ(a * b - Real(1) * Real(1), 0);
    EXPECT_LT(exactDifferenceOfProducts(a, b, 1, 1), 0);
    EXPECT_GT(exactDifferenceOfProducts(1, 1, a, b), 0);
    EXPECT_EQ(exactDifferenceOfProducts(a, b, b, a), 0);
}

// The test: rays exactly at the shared edges and vertices of closed meshes, in every
// structure, the four queries, on this level's lanes. With the watertight test none slips
// through, and the structures give the naive list's hits (the same primitive or one as near, as
// accel_agreement_test asks). With Moller-Trumbore some do (in the naive list and the KD tree,
// its packets included; the other structures give their bits), so the rays are ones that need it.
TEST_P(WatertightMeshes, NoRaySlipsThroughAClosedMesh) {
    for (const ClosedMesh& closed : closedMeshes()) {
        const Primitives prims = closed.mesh.primitives();
        const std::vector<AimedRay> rays = edgeAndVertexRays(closed.mesh, closed.onlyInsideFaceAlongAxes);
        const auto naive = buildAccelerator(prims, settingsFor(AccelKind::Naive, TriangleTest::Watertight));
        for (AccelKind kind : kKinds) {
            const auto accel = buildAccelerator(prims, settingsFor(kind, TriangleTest::Watertight));
            const Slips slips = slipsThrough(*accel, rays);
            EXPECT_EQ(slips.total(), 0) << closed.name << ", " << accelKindName(kind) << ", " << rays.size()
                                        << " rays: nearest " << slips.nearest << ", any " << slips.any << ", packets "
                                        << slips.nearestPackets << " and " << slips.anyPackets;
            EXPECT_EQ(differingFromNaive(*naive, *accel, rays), 0) << closed.name << ", " << accelKindName(kind);
        }
        for (AccelKind kind : {AccelKind::Naive, AccelKind::Kd}) {
            const auto mollerTrumbore = buildAccelerator(prims, settingsFor(kind, TriangleTest::MollerTrumbore));
            const Slips slips = slipsThrough(*mollerTrumbore, rays);
            EXPECT_GT(slips.nearest, 0) << closed.name << ", " << accelKindName(kind);
            EXPECT_GT(slips.nearestPackets, 0) << closed.name << ", " << accelKindName(kind);
        }
    }
}

// The KD tree's packets with the watertight test (accel/kd_packet.cpp) give each ray its single
// query's answer, bit for bit: rays from one point outside each mesh to its edges' points in turn,
// neighbours in a packet sharing their octant and their shear's axes.
TEST_P(WatertightMeshes, PacketsHaveTheSingleRaysBits) {
    for (const ClosedMesh& closed : closedMeshes()) {
        const Primitives prims = closed.mesh.primitives();
        const auto kd = buildAccelerator(prims, settingsFor(AccelKind::Kd, TriangleTest::Watertight));
        const Vec3 origin = closed.mesh.centre + Vec3{Real(2.5), Real(1.9), Real(1.3)};
        std::vector<Ray> rays;
        for (const auto& [i, j] : closed.mesh.edges())
            for (Real s : {Real(0.5), Real(1) / Real(3), Real(0.71)})
                rays.push_back({origin, normalize(closed.mesh.vertices[i] +
                                                  (closed.mesh.vertices[j] - closed.mesh.vertices[i]) * s - origin)});
        int differing = 0, hits = 0;
        RayCounters counters;
        for (std::size_t first = 0; first + kPacketSize <= rays.size(); first += kPacketSize) {
            Hit packetHits[kPacketSize];
            bool found[kPacketSize], blocked[kPacketSize];
            const Real ends[kPacketSize] = {4, 4, 4, 4, 4, 4, 4, 4};
            kd->intersectPacket(&rays[first], kPacketSize, kInfinity, packetHits, found, counters);
            kd->occludedPacket(&rays[first], kPacketSize, ends, blocked, counters);
            for (int i = 0; i < kPacketSize; ++i) {
                Hit hit;
                const Ray& ray = rays[first + std::size_t(i)];
                const bool single = kd->intersect(ray, kInfinity, hit, counters);
                hits += single;
                differing += single != found[i] || kd->occluded(ray, 4, counters) != blocked[i] ||
                             (single && (hit.t != packetHits[i].t || hit.prim != packetHits[i].prim ||
                                         hit.u != packetHits[i].u || hit.v != packetHits[i].v));
            }
        }
        EXPECT_EQ(differing, 0) << closed.name;
        EXPECT_GT(hits, int(rays.size()) / 4) << closed.name;
    }
}
