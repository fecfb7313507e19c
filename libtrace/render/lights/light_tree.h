// Choosing one of many lights for a shading point: a binary tree over the emitters that lie in the
// scene (point and spot lights with falloff, emissive triangles), each node bounding its lights'
// positions, the directions they face and their intensity (Conty Estevez and Kulla 2018,
// "Importance Sampling of Many Lights with Adaptive Tree Splitting"; pbrt-v4's BVHLightSampler and
// Cycles' light tree are the same idea). A sample walks down from the root, taking each child with
// probability proportional to an upper bound of what its lights can send to the point, so that a
// light far away, behind the point's surface or facing away from it is rarely (or never) chosen,
// where a choice in proportion to power alone picks it as often from everywhere.
//
// The bound is conservative: a node whose lights can light the point gets a positive importance,
// so every light that contributes keeps a positive probability and the estimate stays unbiased.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "core/aabb.h"
#include "core/vec3.h"

namespace rt {

// The largest Real below 1: a sample number stretched back over [0, 1) after a choice stays below it.
inline constexpr Real kBelowOne = Real(1) - std::numeric_limits<Real>::epsilon() / 2;

// A cone of directions: every direction within acos(cosSpread) of `axis`; cosSpread -1 is the
// whole sphere.
struct DirectionCone {
    Vec3 axis{0, 0, 1};
    Real cosSpread = 1;
};

// The smallest cone (of this construction) that holds both.
DirectionCone unite(const DirectionCone& a, const DirectionCone& b);

// What a node of the tree knows of its lights.
struct LightBounds {
    Aabb box;               // where they are
    DirectionCone normals;  // the directions they face (theta_o)
    Real cosEmission = 0;   // cos theta_e: how far past a normal they still send light (a triangle: 90 degrees)
    Real intensity = 0;     // the sum of their peak radiant intensities (luminance, per steradian)
};

LightBounds unite(const LightBounds& a, const LightBounds& b);

class LightTree {
public:
    LightTree() = default;
    // A tree over `lights`; light i of a sample or probability is lights[i]. Built on one thread,
    // the same tree for any input of the same order.
    explicit LightTree(const std::vector<LightBounds>& lights);

    bool empty() const { return nodes_.empty(); }
    std::size_t size() const { return leafOf_.size(); }

    struct Choice {
        std::uint32_t light;
        Real probability;
    };
    // One light for the surface point p with normal n, u in [0, 1) choosing; none when no light
    // can reach p.
    std::optional<Choice> sample(const Vec3& p, const Vec3& n, Real u) const;
    // The probability with which sample() at p and n chooses `light`.
    Real probability(std::uint32_t light, const Vec3& p, const Vec3& n) const;

private:
    // A node's bounds as the walk reads them, computed once at the build.
    struct Bounds {
        Vec3 centre;  // of the box's bounding sphere
        Real radiusSquared = 0;
        Vec3 axis;  // the normals' cone
        Real cosSpread = 1, sinSpread = 0;
        Real cosEmission = 0;
        Real intensity = 0;

        Bounds() = default;
        explicit Bounds(const LightBounds& b);
        // An upper bound, up to a common scale, of the irradiance these lights give a surface at p
        // with unit normal n (facing the side lights may come from): intensity / distance^2, times
        // the cosines at the emitters and at p, each at the most favourable angle the box allows.
        // Zero only where none of the lights can send light to p's side of its surface.
        Real importance(const Vec3& p, const Vec3& n) const;
    };
    struct Node {
        Bounds bounds;
        std::uint32_t secondChild = 0;  // interior: its first child follows it; leaf: unused
        std::uint32_t light = 0;        // leaf: the light it holds
        std::uint32_t parent = 0;       // the root's is itself
        bool leaf = false;
    };
    struct Build;
    // The chances of the interior node's two children at p and n; both 0 when neither can light it.
    std::pair<Real, Real> childProbabilities(std::uint32_t node, const Vec3& p, const Vec3& n) const;

    std::vector<Node> nodes_;  // depth first: the root at 0
    std::vector<std::uint32_t> leafOf_;
};

}  // namespace rt
