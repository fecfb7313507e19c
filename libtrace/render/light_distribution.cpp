#include "render/light_distribution.h"

#include <algorithm>
#include <cmath>

#include "render/light_sample.h"

namespace rt {

namespace {

// Below this the power estimate of an emitter counts as none.
constexpr double kNoPower = 1e-12;

}  // namespace

LightDistribution::LightDistribution(const Scene& scene, const ImageTextures* images)
    : scene_(scene), environment_(scene, images) {
    // The scene's bounding sphere: the thesis's unattenuated point lights and the environment
    // send their light over it.
    const Aabb box = scene.primitives.bounds();
    const double radius = box.empty() ? 1 : std::max(0.5 * double(length(box.diagonal())), 1e-6);
    const double sphereArea = 4 * kPi * radius * radius;
    std::vector<double> power;
    const bool emitters = scene.hasEmissiveMaterial();
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        if (scene.lights[i].headlight && emitters) continue;  // the emitters light the scene (scene/light.h)
        entries_.push_back({LightSample::Source::Point, std::uint32_t(i)});
        power.push_back(sphereArea * double(luminance(scene.lights[i].color)));  // irradiance I everywhere
    }
    const auto triangles = scene.primitives.all<Triangle>();
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const std::uint32_t id = scene.primitives.material(std::uint32_t(i));
        if (id >= scene.materials.size()) continue;
        const double radiance = luminance(scene.materials[id].emission);
        if (!(radiance > kNoPower)) continue;
        triangleEntry_[std::uint32_t(i)] = entries_.size();
        entries_.push_back({LightSample::Source::Triangle, std::uint32_t(i)});
        power.push_back(kPi * radiance * double(triangles[i].area()));  // Lambertian, front side
    }
    const double background = environment_.averageLuminance();
    if (background > kNoPower) {
        // an environment of mean radiance L gives irradiance pi L over the bounding sphere
        entries_.push_back({LightSample::Source::Environment, 0});
        power.push_back(sphereArea * kPi * background);
    }
    double total = 0;
    for (const double p : power) cdf_.push_back(total += p);
    if (!(total > 0)) {
        entries_.clear();
        cdf_.clear();
        triangleEntry_.clear();
        return;
    }
    for (double& c : cdf_) c /= total;
    cdf_.back() = 1;
    if (!entries_.empty() && entries_.back().source == LightSample::Source::Environment)
        environmentProbability_ = probability(entries_.size() - 1);
}

Real LightDistribution::probability(std::size_t entry) const {
    return Real(cdf_[entry] - (entry == 0 ? 0 : cdf_[entry - 1]));
}

std::optional<LightSample> LightDistribution::sample(const Vec3& from, Real u, Real u1, Real u2) const {
    if (cdf_.empty()) return std::nullopt;
    const std::size_t entry =
        std::min(std::size_t(std::upper_bound(cdf_.begin(), cdf_.end(), double(u)) - cdf_.begin()), cdf_.size() - 1);
    const Real chosen = probability(entry);
    LightSample s;
    s.source = entries_[entry].source;
    s.index = entries_[entry].index;
    switch (s.source) {
        case LightSample::Source::Point: {  // point, spot or directional: render/light_sample.h
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

Real LightDistribution::pdfTriangle(std::uint32_t prim, const Vec3& direction, Real distance) const {
    const auto it = triangleEntry_.find(prim);
    if (it == triangleEntry_.end()) return 0;
    const Triangle& tri = scene_.primitives.all<Triangle>()[prim];
    const Real cosine = -dot(tri.normal(), direction);
    if (!(cosine > 0)) return 0;
    return probability(it->second) * distance * distance / (cosine * tri.area());
}

}  // namespace rt
