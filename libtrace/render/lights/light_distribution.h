// What the path tracer's next-event estimation samples: the scene's lights (point, spot and
// directional, each a delta light), its emissive triangles as area lights (emitting from their
// front, the side their winding faces), and the environment (a non-black background, or an image:
// render/lights/environment_light.h). Emissive spheres, cylinders and cones are not sampled: they light the
// scene through the paths that hit them (docs/path-tracing.md).
//
// LightSampler::Power picks each light in proportion to an estimate of the power it sends into the
// scene (pbrt-v4's power light sampler). LightSampler::Tree (the default) does so between the lights
// that are everywhere alike (the environment, directional lights, the thesis's point lights without
// falloff) and the local lights as one group, and picks within that group by a light tree
// (render/lights/light_tree.h), by what each light can send to the shading point.
#pragma once

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/color.h"
#include "core/vec3.h"
#include "render/lights/environment_light.h"
#include "render/lights/light_tree.h"
#include "render/render_settings.h"
#include "scene/scene.h"

namespace rt {

struct LightSample {
    enum class Source { Point, Triangle, Environment };  // Point: any Scene::lights entry
    Source source = Source::Point;
    std::uint32_t index = 0;  // Point: in Scene::lights; Triangle: in Scene::primitives
    Real b1 = 0, b2 = 0;      // Triangle: the point's barycentric weights of p1 and p2
    Vec3 direction;           // unit, from the shading point
    Real distance = kInfinity;
    Real pdf = 0;  // per unit solid angle, the choice of the light included; Point: the choice only
    bool delta() const { return source == Source::Point; }
};

class LightDistribution {
public:
    // The emitters of a flattened scene: its lights, and materials with a non-black emission
    // make their triangles area lights (their share of the samples follows the mean of the
    // emission texture over each triangle, looked up through the context's lookups). A
    // headlight is left out when there are such materials: they light the scene, as they do a
    // model in Blender or a glTF viewer, and its file renders as its converted XML does.
    // The context's lookups also read an environment image.
    explicit LightDistribution(const ShadingContext& context, LightSampler sampler = LightSampler::Tree);

    bool empty() const { return cdf_.empty(); }
    // One light for the point `from` on a surface of unit normal `normal` (facing the side light
    // is wanted on): u picks it, (u1, u2) the point on it.
    std::optional<LightSample> sample(const Vec3& from, const Vec3& normal, Real u, Real u1, Real u2) const;
    // The density per solid angle with which sample() at `from` and `normal` would have chosen the
    // point at `distance` along unit `direction` on primitive `prim` (0: not an area light), and
    // the background's direction, for multiple importance sampling.
    Real pdfTriangle(std::uint32_t prim, const Vec3& from, const Vec3& normal, const Vec3& direction,
                     Real distance) const;
    Real pdfEnvironment(const Vec3& direction) const {
        return environmentProbability_ > 0 ? environmentProbability_ * environment_.pdf(direction) : 0;
    }
    const EnvironmentLight& environment() const { return environment_; }

private:
    struct Entry {
        LightSample::Source source;
        std::uint32_t index;  // in Scene::lights or Scene::primitives
        bool inTree = false;
        std::uint32_t slot = 0;  // its light in the tree, or else its choice
    };
    void addChoice(std::uint32_t entry, double power);
    Real probability(std::size_t choice) const;
    Real probability(const Entry& entry, const Vec3& from, const Vec3& normal) const;
    // Light `entry`, chosen with probability `chosen`: a point on it for `from`.
    std::optional<LightSample> sampleEntry(const Entry& entry, Real chosen, const Vec3& from, Real u1, Real u2) const;

    static constexpr std::uint32_t kTree = ~std::uint32_t(0);  // the choice of the light tree

    const Scene& scene_;
    EnvironmentLight environment_;
    std::vector<Entry> entries_;          // every light
    std::vector<std::uint32_t> choices_;  // what the CDF chooses between: an entry, or kTree
    std::vector<double> cdf_;             // running sums of power over choices_, normalised to end at 1
    LightTree tree_;                      // over the entries in treeEntries_
    std::vector<std::uint32_t> treeEntries_;
    std::size_t treeChoice_ = 0;
    std::unordered_map<std::uint32_t, std::uint32_t> triangleEntry_;
    Real environmentProbability_ = 0;
};

}  // namespace rt
