#include "render/lights/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rt {

namespace {

// An angle in [0, pi] by its cosine and sine, so that bounds subtract angles without acos.
struct Angle {
    Real cos, sin;
};

Angle angleOfCosine(Real cosine) {
    const Real c = std::clamp(cosine, Real(-1), Real(1));
    return {c, std::sqrt(std::max(Real(0), 1 - c * c))};
}

// max(a - b, 0): what is left of angle a once b is taken off, never negative.
Angle reduced(const Angle& a, const Angle& b) {
    if (a.cos >= b.cos) return {1, 0};  // a <= b
    return {a.cos * b.cos + a.sin * b.sin, a.sin * b.cos - a.cos * b.sin};
}

// The angle between unit vectors, accurate near 0 and pi where acos(dot) is not.
Real angleBetween(const Vec3& a, const Vec3& b) {
    if (dot(a, b) < 0) return kPi - 2 * std::asin(std::min(Real(1), length(a + b) / 2));
    return 2 * std::asin(std::min(Real(1), length(a - b) / 2));
}

// Below this squared distance a point counts as on a light: keeps 1 / d^2 finite.
constexpr Real kMinDistanceSquared = Real(1e-12);

}  // namespace

DirectionCone unite(const DirectionCone& a, const DirectionCone& b) {
    const Real thetaA = std::acos(std::clamp(a.cosSpread, Real(-1), Real(1)));
    const Real thetaB = std::acos(std::clamp(b.cosSpread, Real(-1), Real(1)));
    const Real between = angleBetween(a.axis, b.axis);
    if (std::min(between + thetaB, kPi) <= thetaA) return a;  // b lies inside a
    if (std::min(between + thetaA, kPi) <= thetaB) return b;
    // the cone whose edge touches the far edges of both: its axis turned from a's towards b's
    const Real theta = (thetaA + between + thetaB) / 2;
    const Vec3 across = b.axis - a.axis * dot(a.axis, b.axis);  // b's axis with a's part taken off
    if (theta >= kPi || !(dot(across, across) > 0)) return {a.axis, -1};
    const Real turn = theta - thetaA;
    return {normalize(a.axis * std::cos(turn) + normalize(across) * std::sin(turn)), std::cos(theta)};
}

LightBounds unite(const LightBounds& a, const LightBounds& b) {
    if (!(a.intensity > 0)) return b;
    if (!(b.intensity > 0)) return a;
    LightBounds u = a;
    u.box.extend(b.box);
    u.normals = unite(a.normals, b.normals);
    u.cosEmission = std::min(a.cosEmission, b.cosEmission);
    u.intensity = a.intensity + b.intensity;
    return u;
}

LightTree::Bounds::Bounds(const LightBounds& b)
    : centre(b.box.center()),
      radiusSquared(b.box.empty() ? 0 : dot(b.box.diagonal(), b.box.diagonal()) / 4),
      axis(b.normals.axis),
      cosSpread(angleOfCosine(b.normals.cosSpread).cos),
      sinSpread(angleOfCosine(b.normals.cosSpread).sin),
      cosEmission(b.cosEmission),
      intensity(b.intensity) {}

Real LightTree::Bounds::importance(const Vec3& p, const Vec3& n) const {
    const Vec3 toPoint = p - centre;
    const Real distanceSquared = dot(toPoint, toPoint);
    // Inside the bounding sphere the lights may lie in any direction: no cosine bounds the sum.
    if (distanceSquared <= radiusSquared) return intensity / std::max(radiusSquared, kMinDistanceSquared);
    const Vec3 w = toPoint / std::sqrt(distanceSquared);  // from the lights towards p
    // theta_b: the half-angle the bounding sphere covers as seen from p
    const Angle spreadOfBox = angleOfCosine(std::sqrt(std::max(Real(0), 1 - radiusSquared / distanceSquared)));
    // At the emitters: the smallest angle any of them can have between its normal and p, past the
    // normals' cone and the box's spread; beyond theta_e they send nothing.
    const Angle pastNormals = reduced(angleOfCosine(dot(axis, w)), {cosSpread, sinSpread});
    const Angle atEmitter = reduced(pastNormals, spreadOfBox);
    if (atEmitter.cos < cosEmission) return 0;
    // At p: the smallest angle between n and a direction into the box; at 90 degrees or more every
    // light is below p's surface.
    const Angle atPoint = reduced(angleOfCosine(-dot(n, w)), spreadOfBox);
    if (!(atPoint.cos > 0)) return 0;
    return intensity * std::max(atEmitter.cos, Real(0)) * atPoint.cos / distanceSquared;
}

// ---------------------------------------------------------------------------------------------
// Build: top down, each node split where the surface area orientation heuristic (SAOH, Conty
// Estevez and Kulla 2018 section 4.4) is least, over buckets of the lights' centres along each axis.

namespace {

constexpr int kBuckets = 12;

// The solid-angle measure of a node's orientation bounds, M_Omega in the paper: the integral of
// the clamped cosine over the directions its lights may send light in.
Real orientationMeasure(const LightBounds& b) {
    const Real thetaO = std::acos(std::clamp(b.normals.cosSpread, Real(-1), Real(1)));
    const Real thetaE = std::acos(std::clamp(b.cosEmission, Real(-1), Real(1)));
    const Real thetaW = std::min(thetaO + thetaE, kPi);
    const Real sinO = std::sin(thetaO), cosO = std::cos(thetaO);
    return 2 * kPi * (1 - cosO) +
           kPi / 2 * (2 * thetaW * sinO - std::cos(thetaO - 2 * thetaW) - 2 * thetaO * sinO + cosO);
}

Real splitCost(const LightBounds& b) { return b.intensity * orientationMeasure(b) * b.box.surfaceArea(); }

}  // namespace

struct LightTree::Build {
    const std::vector<LightBounds>& lights;
    std::vector<Node>& nodes;
    std::vector<std::uint32_t>& leafOf;

    std::uint32_t node(std::uint32_t* first, std::uint32_t* last, std::uint32_t parent) {
        const auto index = std::uint32_t(nodes.size());
        nodes.push_back({});
        nodes[index].parent = parent;
        if (last - first == 1) {
            nodes[index].bounds = Bounds(lights[*first]);
            nodes[index].light = *first;
            nodes[index].leaf = true;
            leafOf[*first] = index;
            return index;
        }
        LightBounds all;
        for (const std::uint32_t* i = first; i != last; ++i) all = unite(all, lights[*i]);
        std::uint32_t* middle = split(first, last, all);
        node(first, middle, index);
        const std::uint32_t second = node(middle, last, index);
        nodes[index].bounds = Bounds(all);
        nodes[index].secondChild = second;
        return index;
    }

    // Partitions [first, last) in two non-empty parts at the cheapest bucket boundary; in the
    // middle when the centres coincide.
    std::uint32_t* split(std::uint32_t* first, std::uint32_t* last, const LightBounds& all) const {
        Aabb centres;
        for (const std::uint32_t* i = first; i != last; ++i) centres.extend(lights[*i].box.center());
        const Vec3 extent = all.box.diagonal();
        const Real longest = std::max({extent.x, extent.y, extent.z});
        Real bestCost = std::numeric_limits<Real>::infinity();
        int bestAxis = -1, bestBucket = 0;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(centres.hi[axis] > centres.lo[axis])) continue;
            std::array<LightBounds, kBuckets> buckets{};
            for (const std::uint32_t* i = first; i != last; ++i) {
                const int b = bucketOf(lights[*i], centres, axis);
                buckets[b] = unite(buckets[b], lights[*i]);
            }
            // a long thin node should be cut across its length (the paper's K_r)
            const Real stretch = longest / extent[axis];
            for (int cut = 1; cut < kBuckets; ++cut) {
                LightBounds below, above;
                for (int b = 0; b < cut; ++b) below = unite(below, buckets[b]);
                for (int b = cut; b < kBuckets; ++b) above = unite(above, buckets[b]);
                if (!(below.intensity > 0) || !(above.intensity > 0)) continue;
                const Real cost = stretch * (splitCost(below) + splitCost(above));
                if (cost < bestCost) bestCost = cost, bestAxis = axis, bestBucket = cut;
            }
        }
        if (bestAxis < 0) return first + (last - first) / 2;
        std::uint32_t* middle = std::partition(
            first, last, [&](std::uint32_t i) { return bucketOf(lights[i], centres, bestAxis) < bestBucket; });
        return middle == first || middle == last ? first + (last - first) / 2 : middle;
    }

    static int bucketOf(const LightBounds& light, const Aabb& centres, int axis) {
        const Real t = (light.box.center()[axis] - centres.lo[axis]) / (centres.hi[axis] - centres.lo[axis]);
        return std::clamp(int(t * kBuckets), 0, kBuckets - 1);
    }
};

LightTree::LightTree(const std::vector<LightBounds>& lights) : leafOf_(lights.size()) {
    if (lights.empty()) return;
    std::vector<std::uint32_t> order(lights.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = std::uint32_t(i);
    nodes_.reserve(2 * lights.size() - 1);
    Build{lights, nodes_, leafOf_}.node(order.data(), order.data() + order.size(), 0);
}

// ---------------------------------------------------------------------------------------------
// Sampling

std::pair<Real, Real> LightTree::childProbabilities(std::uint32_t node, const Vec3& p, const Vec3& n) const {
    const Real first = nodes_[node + 1].bounds.importance(p, n);
    const Real second = nodes_[nodes_[node].secondChild].bounds.importance(p, n);
    const Real total = first + second;
    if (!(total > 0)) return {0, 0};
    return {first / total, second / total};
}

std::optional<LightTree::Choice> LightTree::sample(const Vec3& p, const Vec3& n, Real u) const {
    if (nodes_.empty()) return std::nullopt;
    std::uint32_t node = 0;
    Real probability = 1;
    while (!nodes_[node].leaf) {
        const auto [first, second] = childProbabilities(node, p, n);
        if (!(first + second > 0)) return std::nullopt;
        // u chooses the child and is stretched back over [0, 1) for the next choice
        if (u < first) {
            u = std::min(u / first, kBelowOne);
            probability *= first;
            node = node + 1;
        } else {
            u = std::min((u - first) / second, kBelowOne);
            probability *= second;
            node = nodes_[node].secondChild;
        }
    }
    // a lone light is the root: it is chosen wherever it can light p
    if (node == 0 && !(nodes_[0].bounds.importance(p, n) > 0)) return std::nullopt;
    return Choice{nodes_[node].light, probability};
}

Real LightTree::probability(std::uint32_t light, const Vec3& p, const Vec3& n) const {
    if (light >= leafOf_.size()) return 0;
    std::uint32_t node = leafOf_[light];
    if (node == 0) return nodes_[0].bounds.importance(p, n) > 0 ? 1 : 0;
    Real probability = 1;
    while (node != 0) {
        const std::uint32_t parent = nodes_[node].parent;
        const auto [first, second] = childProbabilities(parent, p, n);
        probability *= node == parent + 1 ? first : second;
        node = parent;
    }
    return probability;
}

}  // namespace rt
