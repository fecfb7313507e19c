// Checks of a structure's packets (Accelerator::intersectPacket, occludedPacket) against its single
// rays, bit for bit, and the rays they are checked with: camera rays in 4x2 tiles, the shadow rays
// rt-render traces, narrow cones. Shared by the KD and BSP trees' packet tests (kd_packet_test.cpp)
// and the BVH's (bvh_packet_test.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "accel/accelerator.h"
#include "core/random.h"
#include "render/camera_rays.h"
#include "render/surface.h"
#include "scene/scene.h"
#include "test_util.h"

namespace rt::test {

inline bool identical(bool foundA, const Hit& a, bool foundB, const Hit& b) {
    return foundA == foundB &&
           (!foundA || (a.prim == b.prim && sameBits(a.t, b.t) && sameBits(a.u, b.u) && sameBits(a.v, b.v)));
}

// Where the shadow ray along rays[i] ends, so that a packet mixes every case: well before, at
// (a hit at exactly tMax does not block), just past and well past its nearest hit before `tMax`,
// or `tMax` itself; rays that hit nothing end at `tMax` or short of the scene.
inline Real shadowEnd(const Accelerator& tree, const Ray& ray, std::size_t i, Real tMax) {
    Hit hit;
    RayCounters unused;
    if (!tree.intersect(ray, tMax, hit, unused)) return i % 2 ? tMax : Real(0.25);
    switch (i % 5) {
        case 0:
            return hit.t / 2;
        case 1:
            return hit.t;
        case 2:
            return std::nextafter(hit.t, kInfinity);
        case 3:
            return tMax;
        default:
            return hit.t * 2;
    }
}

// What a packet's counted work is checked against: the single rays' sums (the KD and BSP trees'
// packets visit and test what each ray would alone), or nothing (the BVH's packets visit the
// nodes in the packet's order, which counts work of its own).
enum class Counts { Same, Own };

// Traces `rays` as shadow rays, rays[i] ending at ends[i], in packets of `packetSize` (the last
// may be shorter) and one by one; describes the first packets whose answers, or with
// Counts::Same counted work, differ, empty if none does.
inline std::string shadowDisagreements(const Accelerator& tree, const std::vector<Ray>& rays,
                                       const std::vector<Real>& ends, int packetSize, Counts counts = Counts::Same) {
    std::ostringstream out;
    int reported = 0;
    for (std::size_t first = 0; first < rays.size() && reported < 5; first += std::size_t(packetSize)) {
        const int count = int(std::min<std::size_t>(std::size_t(packetSize), rays.size() - first));
        bool blocked[kPacketSize];
        RayCounters packet, single;
        tree.occludedPacket(&rays[first], count, &ends[first], blocked, packet);
        for (int i = 0; i < count; ++i) {
            const std::size_t r = first + std::size_t(i);
            const bool expected = tree.occluded(rays[r], ends[r], single);
            if (blocked[i] == expected) continue;
            out << tree.stats().name << " shadow ray " << r << " o=" << rays[r].origin << " d=" << rays[r].direction
                << " tMax " << ends[r] << ": packet " << blocked[i] << ", single " << expected << '\n';
            ++reported;
        }
        if (counts == Counts::Own ||
            (packet.traversalSteps == single.traversalSteps && packet.intersectionTests == single.intersectionTests))
            continue;
        out << tree.stats().name << " shadow packet at " << first << ": steps " << packet.traversalSteps << " vs "
            << single.traversalSteps << ", tests " << packet.intersectionTests << " vs " << single.intersectionTests
            << '\n';
        ++reported;
    }
    return out.str();
}

// Traces `rays` in packets of `packetSize` (the last may be shorter) and one by one, for their
// nearest hits and as shadow rays (shadowDisagreements); describes the first rays whose answers
// differ, empty if none does. `naive`, if given, checks the single-ray nearest hits too (the same
// primitive, or an equally near one).
inline std::string packetDisagreements(const Accelerator& tree, const std::vector<Ray>& rays, int packetSize, Real tMax,
                                       const Accelerator* naive = nullptr, Counts counts = Counts::Same) {
    std::ostringstream out;
    RayCounters packetCounters, singleCounters, naiveCounters;
    int reported = 0;
    for (std::size_t first = 0; first < rays.size() && reported < 5; first += std::size_t(packetSize)) {
        const int count = int(std::min<std::size_t>(std::size_t(packetSize), rays.size() - first));
        Hit hits[kPacketSize];
        bool found[kPacketSize];
        tree.intersectPacket(&rays[first], count, tMax, hits, found, packetCounters);
        for (int i = 0; i < count; ++i) {
            const Ray& ray = rays[first + std::size_t(i)];
            Hit single, expected;
            const bool singleFound = tree.intersect(ray, tMax, single, singleCounters);
            const bool packetAgrees = identical(found[i], hits[i], singleFound, single);
            bool naiveAgrees = true;
            if (naive) {
                const bool naiveFound = naive->intersect(ray, tMax, expected, naiveCounters);
                naiveAgrees =
                    naiveFound == singleFound && (!naiveFound || expected.prim == single.prim ||
                                                  std::abs(expected.t - single.t) <= Real(1e-4) * std::abs(expected.t));
            }
            if (packetAgrees && naiveAgrees) continue;
            out << tree.stats().name << " ray " << first + std::size_t(i) << " o=" << ray.origin
                << " d=" << ray.direction << ": packet " << found[i] << " prim " << hits[i].prim << " t " << hits[i].t
                << "; single " << singleFound << " prim " << single.prim << " t " << single.t << "; naive prim "
                << expected.prim << " t " << expected.t << '\n';
            ++reported;
        }
    }
    if (counts == Counts::Same && (packetCounters.traversalSteps != singleCounters.traversalSteps ||
                                   packetCounters.intersectionTests != singleCounters.intersectionTests))
        out << tree.stats().name << " nearest hits: steps " << packetCounters.traversalSteps << " vs "
            << singleCounters.traversalSteps << ", tests " << packetCounters.intersectionTests << " vs "
            << singleCounters.intersectionTests << '\n';
    std::vector<Real> ends;
    for (std::size_t i = 0; i < rays.size(); ++i) ends.push_back(shadowEnd(tree, rays[i], i, tMax));
    out << shadowDisagreements(tree, rays, ends, packetSize, counts);
    return out.str();
}

// The camera rays of a width x height view in 4x2 tiles, as rt-render traces them.
inline std::vector<Ray> cameraTiles(const Camera& camera, int width, int height) {
    const CameraRays cameraRays(camera, width, height);
    std::vector<Ray> rays;
    for (int y0 = 0; y0 < height; y0 += 2)
        for (int x0 = 0; x0 < width; x0 += 4)
            for (int i = 0; i < kPacketSize; ++i)
                rays.push_back(cameraRays.at(Real(x0 + i % 4) + Real(0.5), Real(y0 + i / 4) + Real(0.5)));
    return rays;
}

// The shadow rays rt-render traces for a width x height view (Tracer::pixelRun): from above the
// first hit of each pixel's camera ray, row by row, to each light of the scene, ending there, and
// to a light at infinity (ending at kInfinity); `ends` receives where each ends.
inline std::vector<Ray> shadowRaysOf(const Scene& scene, const Accelerator& tree, int width, int height,
                                     std::vector<Real>& ends) {
    const CameraRays cameraRays(scene.camera, width, height);
    const Real epsilon = secondaryRayOffset(scene.primitives);
    std::vector<Vec3> origins;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Ray ray = cameraRays.at(Real(x) + Real(0.5), Real(y) + Real(0.5));
            Hit hit;
            RayCounters unused;
            if (!tree.intersect(ray, kInfinity, hit, unused)) continue;
            const Vec3 p = ray.at(hit.t);
            Vec3 n = scene.primitives.normal(hit.prim, p);
            if (dot(n, ray.direction) > 0) n = -n;
            origins.push_back(p + n * epsilon);
        }
    std::vector<Ray> rays;
    for (const Light& light : scene.lights)
        for (const Vec3& origin : origins) {
            const Vec3 d = light.position - origin;
            rays.push_back({origin, d / length(d), true});
            ends.push_back(length(d));
        }
    for (const Vec3& origin : origins) {
        rays.push_back({origin, normalize(Vec3{1, 2, 3}), true});
        ends.push_back(kInfinity);
    }
    return rays;
}

// Packets of rays from one origin in a narrow cone around a random axis: coherent, but some
// cones straddle an octant's boundary (traced one by one) and some start inside the scene.
inline std::vector<Ray> coneRays(int packets, std::uint64_t seed) {
    SplitMix64 rng(seed);
    const auto uniform = [&](Real lo, Real hi) { return lo + (hi - lo) * Real(rng.uniform()); };
    std::vector<Ray> rays;
    for (int p = 0; p < packets; ++p) {
        const Vec3 origin{uniform(-1.5, 1.5), uniform(-1.5, 1.5), uniform(-1.5, 1.5)};
        const Vec3 axis = normalize(Vec3{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)});
        const Real spread = p % 2 ? Real(0.02) : Real(0.2);
        for (int i = 0; i < kPacketSize; ++i)
            rays.push_back({origin, normalize(axis + Vec3{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)} * spread)});
    }
    return rays;
}

// The work counted for `rays` (whole packets of kPacketSize) traced for their nearest hits and as
// shadow rays ending at 1 to 160 and at infinity, in packets and one by one.
struct PacketWork {
    RayCounters packet, single, packetShadows, singleShadows;
};
inline PacketWork countedWork(const Accelerator& accel, const std::vector<Ray>& rays) {
    PacketWork work;
    for (std::size_t first = 0; first < rays.size(); first += kPacketSize) {
        Hit hits[kPacketSize];
        bool found[kPacketSize], blocked[kPacketSize];
        const Real ends[kPacketSize] = {1, 5, 10, 20, 40, 80, 160, kInfinity};
        accel.intersectPacket(&rays[first], kPacketSize, kInfinity, hits, found, work.packet);
        accel.occludedPacket(&rays[first], kPacketSize, ends, blocked, work.packetShadows);
        for (int i = 0; i < kPacketSize; ++i) {
            accel.intersect(rays[first + std::size_t(i)], kInfinity, hits[i], work.single);
            accel.occluded(rays[first + std::size_t(i)], ends[i], work.singleShadows);
        }
    }
    return work;
}

}  // namespace rt::test
