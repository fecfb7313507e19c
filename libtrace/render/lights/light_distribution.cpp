#include "render/lights/light_distribution.h"

#include <algorithm>
#include <cmath>

#include "render/lights/light_sample.h"
#include "render/materials/material.h"
#include "scene/spot_cone.h"

namespace rt {

namespace {

// Below this the power estimate of an emitter counts as none.
constexpr double kNoPower = 1e-12;

// A spot's cone past its inner angle, at least this wide (radians): a spot whose inner and outer
// angles are one still lights the inside of its cone.
constexpr Real kMinSpotFalloff = Real(1e-3);

// Lights that light every point alike, apart from shadows (the environment, directional lights,
// the thesis's point lights without falloff), stay out of the tree: distance says nothing of them.
bool local(const Light& light) {
    return light.type != Light::Type::Directional && light.falloff == Light::Falloff::InverseSquare;
}

// The power a light sends out, by luminance. A light without falloff (and a directional one) gives
// irradiance I everywhere: I over the scene's bounding sphere. A point light of intensity I with
// inverse-square falloff sends 4 pi I; a spot the share of that in its cone, counting the smooth
// edge between its inner and outer angles as half (pbrt-v4's SpotLight::Phi).
double powerOf(const Light& light, double sphereArea) {
    const double intensity = luminance(light.color);
    if (!local(light)) return sphereArea * intensity;
    if (light.type != Light::Type::Spot) return 4 * kPi * intensity;
    const SpotCone cone = spotConeOf(light);
    return 2 * kPi * intensity * (1 - (double(cone.cosInner) + double(cone.cosOuter)) / 2);
}

LightBounds boundsOf(const Light& light) {
    LightBounds b;
    b.box.extend(light.position);
    b.intensity = Real(luminance(light.color));  // the irradiance it gives at distance 1
    if (light.type == Light::Type::Spot) {
        const SpotCone cone = spotConeOf(light);
        b.normals = {light.direction, cone.cosInner};
        b.cosEmission = std::cos(std::max(cone.outer - cone.inner, kMinSpotFalloff));
    } else {
        b.normals.cosSpread = -1;  // every way alike
    }
    return b;
}

LightBounds boundsOf(const Triangle& tri, double radiance) {
    LightBounds b;
    b.box.extend(tri.p0), b.box.extend(tri.p1), b.box.extend(tri.p2);
    b.normals = {tri.normal(), 1};
    b.cosEmission = 0;                          // Lambertian: out to 90 degrees from its normal
    b.intensity = Real(radiance) * tri.area();  // along its normal
    return b;
}

// The radiance triangle `prim` emits, by luminance, for the light's share of the samples: its
// material's emission times the mean of its emission texture over the triangle, read in one lookup
// filtered over the triangle's footprint in the texture (its corners' coordinates as the
// derivatives). A model whose emission texture is black but for a few lit windows then does not
// count every triangle as bright as the windows: those would take nearly every light sample from
// the point lights that light the model (LightsPunctualLamp: all its 6,000 triangles have an
// emission factor of 1). A triangle whose estimate is 0 is not sampled as a light; what it does
// emit is still found, in full, by the paths that hit it (docs/path-tracing.md).
double emittedRadiance(const ShadingContext& context, std::uint32_t prim, const Triangle& tri, const Material& m) {
    if (!m.emission.texture) return luminance(m.emission.color);
    const Vec3 normal = tri.normal();
    const auto at = [&](Real b1, Real b2) {
        const Vec3 p = tri.p0 + (tri.p1 - tri.p0) * b1 + (tri.p2 - tri.p0) * b2;
        return surfaceAt(context.scene.primitives, Ray{p + normal, -normal}, Hit{1, prim, b1, b2});
    };
    const SurfacePoint corner0 = at(0, 0), corner1 = at(1, 0), corner2 = at(0, 1);
    SurfacePoint centre = at(Real(1) / 3, Real(1) / 3);
    centre.dudx = float(corner1.u - corner0.u), centre.dvdx = float(corner1.v - corner0.v);
    centre.dudy = float(corner2.u - corner0.u), centre.dvdy = float(corner2.v - corner0.v);
    return luminance(surfaceEmission(context, m, centre));
}

}  // namespace

LightDistribution::LightDistribution(const ShadingContext& context, LightSampler sampler)
    : scene_(context.scene), environment_(context) {
    const Scene& scene = context.scene;
    // The scene's bounding sphere: the thesis's unattenuated point lights, directional lights and
    // the environment send their light over it.
    const Aabb box = scene.primitives.bounds();
    const double radius = box.empty() ? 1 : std::max(0.5 * double(length(box.diagonal())), 1e-6);
    const double sphereArea = 4 * kPi * radius * radius;
    const bool useTree = sampler == LightSampler::Tree;
    std::vector<LightBounds> treeLights;
    double treePower = 0;
    // Each light joins the tree (a local light, with a tree) or is a choice of its own.
    const auto add = [&](LightSample::Source source, std::uint32_t index, double power, bool isLocal,
                         const auto& bounds) {
        const auto entry = std::uint32_t(entries_.size());
        entries_.push_back({source, index});
        if (useTree && isLocal) {
            entries_.back().inTree = true;
            entries_.back().slot = std::uint32_t(treeEntries_.size());
            treeEntries_.push_back(entry);
            treeLights.push_back(bounds());
            treePower += power;
        } else {
            addChoice(entry, power);
        }
    };
    const bool emitters = scene.hasEmissiveMaterial();
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (light.headlight && emitters) continue;  // the emitters light the scene (scene/light.h)
        add(LightSample::Source::Point, std::uint32_t(i), powerOf(light, sphereArea), local(light),
            [&] { return boundsOf(light); });
    }
    const auto triangles = scene.primitives.all<Triangle>();
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const std::uint32_t id = scene.primitives.material(std::uint32_t(i));
        if (id >= scene.materials.size() || !(luminance(scene.materials[id].emission.color) > kNoPower)) continue;
        const double radiance = emittedRadiance(context, std::uint32_t(i), triangles[i], scene.materials[id]);
        if (!(radiance > kNoPower)) continue;
        triangleEntry_[std::uint32_t(i)] = std::uint32_t(entries_.size());
        add(LightSample::Source::Triangle, std::uint32_t(i), kPi * radiance * double(triangles[i].area()), true,
            [&] { return boundsOf(triangles[i], radiance); });  // power: Lambertian, front side
    }
    const double background = environment_.averageLuminance();
    if (background > kNoPower) {
        // an environment of mean radiance L gives irradiance pi L over the bounding sphere
        add(LightSample::Source::Environment, 0, sphereArea * kPi * background, false, [] { return LightBounds{}; });
    }
    if (!treeLights.empty()) {
        tree_ = LightTree(treeLights);
        treeChoice_ = choices_.size();
        addChoice(kTree, treePower);
    }
    const double total = cdf_.empty() ? 0 : cdf_.back();
    if (!(total > 0)) {
        entries_.clear();
        choices_.clear();
        cdf_.clear();
        triangleEntry_.clear();
        return;
    }
    for (double& c : cdf_) c /= total;
    cdf_.back() = 1;
    for (const Entry& e : entries_)
        if (e.source == LightSample::Source::Environment) environmentProbability_ = probability(e.slot);
}

void LightDistribution::addChoice(std::uint32_t entry, double power) {
    if (entry != kTree) entries_[entry].slot = std::uint32_t(choices_.size());
    choices_.push_back(entry);
    cdf_.push_back((cdf_.empty() ? 0 : cdf_.back()) + power);
}

Real LightDistribution::probability(std::size_t choice) const {
    return Real(cdf_[choice] - (choice == 0 ? 0 : cdf_[choice - 1]));
}

Real LightDistribution::probability(const Entry& entry, const Vec3& from, const Vec3& normal) const {
    if (!entry.inTree) return probability(entry.slot);
    return probability(treeChoice_) * tree_.probability(entry.slot, from, normal);
}

std::optional<LightSample> LightDistribution::sample(const Vec3& from, const Vec3& normal, Real u, Real u1,
                                                     Real u2) const {
    if (cdf_.empty()) return std::nullopt;
    const std::size_t choice =
        std::min(std::size_t(std::upper_bound(cdf_.begin(), cdf_.end(), double(u)) - cdf_.begin()), cdf_.size() - 1);
    const Real chosen = probability(choice);
    if (choices_[choice] != kTree) return sampleEntry(entries_[choices_[choice]], chosen, from, u1, u2);
    // u, stretched over [0, 1) within the tree's share of the CDF, walks down the tree
    const double start = choice == 0 ? 0 : cdf_[choice - 1];
    const Real uTree = std::min(Real((double(u) - start) / (cdf_[choice] - start)), kBelowOne);
    const std::optional<LightTree::Choice> light = tree_.sample(from, normal, std::max(uTree, Real(0)));
    if (!light) return std::nullopt;
    return sampleEntry(entries_[treeEntries_[light->light]], chosen * light->probability, from, u1, u2);
}

std::optional<LightSample> LightDistribution::sampleEntry(const Entry& entry, Real chosen, const Vec3& from, Real u1,
                                                          Real u2) const {
    LightSample s;
    s.source = entry.source;
    s.index = entry.index;
    switch (s.source) {
        case LightSample::Source::Point: {  // point, spot or directional: render/lights/light_sample.h
            const LightIncidence in = lightIncidence(scene_.lights[s.index], from);
            if (!(in.distance > 0) || in.color == Color{}) return std::nullopt;
            s.direction = in.toLight;
            s.distance = in.distance;
            s.pdf = chosen;
            return s;
        }
        case LightSample::Source::Triangle: {
            // uniform in area: fold the unit square onto the triangle
            const Triangle& tri = scene_.primitives.all<Triangle>()[s.index];
            s.b1 = u1, s.b2 = u2;
            if (s.b1 + s.b2 > 1) s.b1 = 1 - s.b1, s.b2 = 1 - s.b2;
            const Vec3 p = tri.p0 + (tri.p1 - tri.p0) * s.b1 + (tri.p2 - tri.p0) * s.b2;
            const Vec3 d = p - from;
            s.distance = length(d);
            if (!(s.distance > 0)) return std::nullopt;
            s.direction = d / s.distance;
            const Real cosine = -dot(tri.normal(), s.direction);
            if (!(cosine > 0)) return std::nullopt;  // its back: emitters shine from the front
            s.pdf = chosen * s.distance * s.distance / (cosine * tri.area());
            return s;
        }
        case LightSample::Source::Environment: {
            const EnvironmentSample sky = environment_.sample(u1, u2);
            if (!(sky.pdf > 0)) return std::nullopt;
            s.direction = sky.direction;
            s.pdf = chosen * sky.pdf;
            return s;
        }
    }
    return std::nullopt;
}

Real LightDistribution::pdfTriangle(std::uint32_t prim, const Vec3& from, const Vec3& normal, const Vec3& direction,
                                    Real distance) const {
    const auto it = triangleEntry_.find(prim);
    if (it == triangleEntry_.end()) return 0;
    const Triangle& tri = scene_.primitives.all<Triangle>()[prim];
    const Real cosine = -dot(tri.normal(), direction);
    if (!(cosine > 0)) return 0;
    return probability(entries_[it->second], from, normal) * distance * distance / (cosine * tri.area());
}

}  // namespace rt
