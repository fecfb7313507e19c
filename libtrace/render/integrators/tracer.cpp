#include "render/integrators/tracer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "render/film/pixel_estimate.h"
#include "render/lights/light_sample.h"
#include "render/materials/material.h"
#include "render/materials/phong.h"
#include "render/normal_map.h"

namespace rt {

namespace {

// A point on the disc of radius r around c facing along `axis` (unit): the light as the
// shading point sees it. Uniform in area: radius r sqrt(u1), angle 2 pi u2.
Vec3 pointOnDisc(const Vec3& c, const Vec3& axis, Real r, SampleRng& rng) {
    Vec3 t, b;
    orthonormalBasis(axis, t, b);
    const Real radius = r * std::sqrt(rng.uniform());
    const Real angle = 2 * kPi * rng.uniform();
    return c + t * (radius * std::cos(angle)) + b * (radius * std::sin(angle));
}

// Whether light arriving as `in` falls on the front of the surface at `s` (not from behind it,
// nor from outside a spot's cone or a light's range): only then it adds light, and a shadow ray
// is traced to it.
bool reaches(const SurfacePoint& s, const LightIncidence& in) {
    return !(dot(s.shadingNormal, in.toLight) <= 0 || in.color == Color{});
}

// What a shadow ray lets through in a scene without glass: all or nothing.
Color passed(bool blocked) { return blocked ? Color{} : Color{1, 1, 1}; }

}  // namespace

Tracer::Tracer(const ShadingContext& context, const Accelerator& accel, const RenderSettings& settings)
    : context_(context),
      accel_(accel),
      settings_(settings),
      camera_(context.scene.camera, settings.width, settings.height),
      environment_(context, false),
      epsilon_(secondaryRayOffset(context.scene.primitives)),
      differentialScale_(std::max(Real(0.125), 1 / std::sqrt(Real(settings.pixelSamples)))),
      coneSpread_(camera_.pixelAngle() * differentialScale_) {
    // Thesis 2.1.3: i_a is the sum of the lights' intensities. The colour of a light with the
    // inverse-square falloff is what it gives at distance 1, no irradiance: it adds nothing.
    for (const Light& light : context_.scene.lights)
        if (light.falloff == Light::Falloff::None) ambientLight_ += light.color;
    for (const Material& m : context_.scene.materials) anyGlass_ = anyGlass_ || m.transmission.passesLight();
    for (const Texture& t : context_.scene.textures)
        filtered_ = filtered_ || (context.images && t.kind == Texture::Kind::Image);
}

Color Tracer::pixel(int x, int y, RenderCounters& counters, float& coverage, PixelAovs* aovs) const {
    const int n = settings_.pixelSamples;
    PixelEstimate estimate;
    AovSums aovSums;
    for (int i = 0; i < n; ++i) {
        const std::optional<RenderCounters> before = aovs ? std::optional(counters) : std::nullopt;
        SampleRng rng{std::uint32_t(x), std::uint32_t(y), std::uint32_t(i), settings_.seed};
        Real sx = Real(0.5), sy = Real(0.5);
        if (n > 1) jitteredGridSample(i, n, rng, sx, sy);
        ++counters.camera.rays;
        // trace() at depth 0, keeping whether the camera ray hit (alpha)
        const Ray ray = camera_.at(Real(x) + sx, Real(y) + sy);
        Hit hit;
        const bool seen = accel_.intersect(ray, kInfinity, hit, counters.camera);
        const Color sample = cameraSample(Real(x) + sx, Real(y) + sy, ray, seen ? &hit : nullptr, rng, counters,
                                          aovs ? &aovSums : nullptr);
        if (!estimate.add(sample, seen)) counters.nonFinite.add(x, y);  // counts as black, and the tool says so
        if (aovs) aovSums.finishSample(*before, counters);
    }
    coverage = estimate.coverage();
    if (aovs) *aovs = aovSums.mean(estimate.varianceOfMean());
    return estimate.mean();
}

bool Tracer::tracesPackets() const {
    return settings_.packets && settings_.pixelSamples == 1 && settings_.aovs.empty();
}

// Neighbouring camera rays share the tree's nodes and leaves, so the packet traversal walks
// them once for all eight (docs/trees.md, "Packets"), and so do their hits' shadow rays to a
// light; what follows stays per pixel.
void Tracer::pixelRun(int x0, int y, int count, RenderCounters& counters, Color* colors, float* coverages) const {
    std::array<Ray, kPacketSize> rays;
    std::array<Hit, kPacketSize> hits;
    std::array<bool, kPacketSize> found{};
    const Real centre = Real(0.5);  // pixel()'s one sample
    for (int i = 0; i < count; ++i) rays[std::size_t(i)] = camera_.at(Real(x0 + i) + centre, Real(y) + centre);
    counters.camera.rays += std::uint64_t(count);
    accel_.intersectPacket(rays.data(), count, kInfinity, hits.data(), found.data(), counters.camera);
    std::array<SurfacePoint, kPacketSize> surfaces;
    std::array<Real, kPacketSize> cones{};
    for (int i = 0; i < count; ++i) {
        const auto k = std::size_t(i);
        if (!found[k]) continue;
        const CameraHit seen = cameraHit(Real(x0 + i) + centre, Real(y) + centre, rays[k], hits[k]);
        surfaces[k] = seen.surface;
        cones[k] = seen.cone;
    }
    std::array<PacketShadows, kPacketSize> shadows{};
    traceShadowPackets(surfaces.data(), found.data(), count, shadows.data(), counters);
    for (int i = 0; i < count; ++i) {
        const auto k = std::size_t(i);
        const int x = x0 + i;
        SampleRng rng{std::uint32_t(x), std::uint32_t(y), 0, settings_.seed};
        // cameraSample's shading, with the shadows found
        const Color sample = found[k]
                                 ? shade(rays[k], hits[k], surfaces[k], 0, false, rng, counters, cones[k], &shadows[k])
                                 : background(rays[k].direction);
        PixelEstimate estimate;
        if (!estimate.add(sample, found[k])) counters.nonFinite.add(x, y);
        colors[i] = estimate.mean();
        coverages[i] = estimate.coverage();
    }
}

// The shadow rays of one light from a run's hits are as coherent as the camera rays were: they
// share a target, or a direction. Lights whose visibility takes more than one ray (soft shadows
// draw random points on the disc) or walks through glass (transmittance) stay per pixel.
void Tracer::traceShadowPackets(const SurfacePoint* surfaces, const bool* found, int count, PacketShadows* shadows,
                                RenderCounters& counters) const {
    if (!settings_.shadows || anyGlass_) return;
    const std::size_t lights = std::min(context_.scene.lights.size(), kPacketLights);
    for (std::size_t l = 0; l < lights; ++l) {
        const Light& light = context_.scene.lights[l];
        if (sampledOverArea(light)) continue;
        std::array<Ray, kPacketSize> rays;
        std::array<Real, kPacketSize> distances;
        std::array<int, kPacketSize> pixels;
        int n = 0;
        for (int i = 0; i < count; ++i) {
            if (!found[i]) continue;
            const LightIncidence in = lightIncidence(light, surfaces[i].point);
            if (!reaches(surfaces[i], in)) continue;
            const ShadowRay shadow = shadowRay(surfaces[i], light, in.toLight);
            rays[std::size_t(n)] = shadow.ray;
            distances[std::size_t(n)] = shadow.distance;
            pixels[std::size_t(n++)] = i;
        }
        if (n == 0) continue;
        counters.shadow.rays += std::uint64_t(n);
        std::array<bool, kPacketSize> blocked{};
        accel_.occludedPacket(rays.data(), n, distances.data(), blocked.data(), counters.shadow);
        for (int k = 0; k < n; ++k) {
            PacketShadows& at = shadows[pixels[std::size_t(k)]];
            at.traced |= 1u << l;
            at.blocked |= std::uint32_t(blocked[std::size_t(k)]) << l;
        }
    }
}

Tracer::CameraHit Tracer::cameraHit(Real px, Real py, const Ray& ray, const Hit& hit) const {
    const RayDifferential differential =
        filtered_ ? camera_.differentialAt(px, py, ray, differentialScale_) : RayDifferential{};
    return {shadedSurfaceAt(context_, ray, hit, differential), differential.radiusAt(hit.t)};
}

Color Tracer::cameraSample(Real px, Real py, const Ray& ray, const Hit* hit, SampleRng& rng, RenderCounters& counters,
                           AovSums* aovSums) const {
    if (!hit) return background(ray.direction);
    // the AOVs take the point, normal and colour the shading uses
    const CameraHit seen = cameraHit(px, py, ray, *hit);
    if (aovSums)
        aovSums->addHit(context_.scene, seen.surface, *hit,
                        surfaceColor(context_, context_.scene.materialOf(hit->prim), seen.surface));
    return shade(ray, *hit, seen.surface, 0, false, rng, counters, seen.cone);
}

Color Tracer::trace(const Ray& ray, int depth, bool inBundle, SampleRng& rng, RenderCounters& counters,
                    const RayDifferential& differential) const {
    Hit hit;
    RayCounters& work = depth == 0 ? counters.camera : counters.reflection;
    if (!accel_.intersect(ray, kInfinity, hit, work)) return background(ray.direction);
    return shadeHit(ray, hit, depth, inBundle, rng, counters, differential);
}

Color Tracer::shadeHit(const Ray& ray, const Hit& hit, int depth, bool inBundle, SampleRng& rng,
                       RenderCounters& counters, const RayDifferential& differential) const {
    return shade(ray, hit, shadedSurfaceAt(context_, ray, hit, differential), depth, inBundle, rng, counters,
                 differential.radiusAt(hit.t));
}

Color Tracer::shade(const Ray& ray, const Hit& hit, const SurfacePoint& s, int depth, bool inBundle, SampleRng& rng,
                    RenderCounters& counters, Real cone, const PacketShadows* known) const {
    const Material& m = context_.scene.materialOf(hit.prim);
    const Color color = surfaceColor(context_, m, s);
    const Vec3 toViewer = -ray.direction;

    // Whitted's model has no light transport from surfaces: an emitter is seen (directly, in
    // mirrors), but lights nothing else.
    Color c = phongAmbient(color, m, ambientLight_) + surfaceEmission(context_, m, s);
    for (std::size_t l = 0; l < context_.scene.lights.size(); ++l) {
        const Light& light = context_.scene.lights[l];
        const LightIncidence in = lightIncidence(light, s.point);
        if (!reaches(s, in)) continue;
        const Color seen = known && known->has(l) ? passed(known->isBlocked(l))
                                                  : visibility(s, light, in.toLight, inBundle, rng, counters);
        if (seen != Color{}) c += phongLight(m, color, s.shadingNormal, in.toLight, toViewer, in.color) * seen;
    }
    // Thesis 2.1, step 6: the reflected intensity is added to the local one; Whitted's
    // transmitted ray too, Fresnel's reflected share of it going to the mirror ray.
    float mirrorWeight = m.phong.reflection;
    if (m.transmission.passesLight() && depth < settings_.reflectionDepth) {
        const float weight = transmissionAt(context_, m, s);
        const RefractionSplit split =
            splitAt(m.transmission, ray.direction, s.shadingNormal, s.geometricNormal, s.frontFace);
        mirrorWeight += weight * split.reflected;
        c += transmitted(s, m, weight, split, depth, inBundle, rng, counters, cone);
    }
    if (mirrorWeight > 0 && depth < settings_.reflectionDepth)
        c += reflection(s, ray.direction, m, depth, inBundle, rng, counters, cone) * mirrorWeight;
    // A ray that leaves a volume has crossed it from where it entered (render/refraction.h).
    if (m.transmission.absorbs() && !s.frontFace) c = c * absorbed(m.transmission, hit.t);
    return c;
}

Color Tracer::visibility(const SurfacePoint& s, const Light& light, const Vec3& toLight, bool inBundle, SampleRng& rng,
                         RenderCounters& counters) const {
    if (!settings_.shadows) return {1, 1, 1};
    if (!sampledOverArea(light)) {
        ++counters.shadow.rays;
        return transmittance(shadowRay(s, light, toLight), counters);
    }
    // Soft shadows: rays to random points of the light's disc, a bundle of them unless in one already.
    const Vec3 origin = shadowOrigin(s);
    const int samples = inBundle ? 1 : settings_.distributedSamples;
    const Vec3 axis = normalize(light.position - origin);
    Color visible;
    for (int i = 0; i < samples; ++i) {
        ++counters.shadow.rays;
        visible += transmittance(towards(origin, pointOnDisc(light.position, axis, light.size, rng)), counters);
    }
    if (samples == 1) return visible;
    const auto n = float(samples);
    return {visible.r / n, visible.g / n, visible.b / n};
}

bool Tracer::sampledOverArea(const Light& light) const {
    return light.type != Light::Type::Directional && settings_.softShadows && light.size > 0;
}

Tracer::ShadowRay Tracer::shadowRay(const SurfacePoint& s, const Light& light, const Vec3& toLight) const {
    // A directional light is infinitely far: anything along the way shadows.
    if (light.type == Light::Type::Directional)
        return {{.origin = shadowOrigin(s), .direction = toLight, .shadow = true}, kInfinity};
    return towards(shadowOrigin(s), light.position);
}

Tracer::ShadowRay Tracer::towards(const Vec3& origin, const Vec3& target) {
    const Vec3 d = target - origin;
    const Real distance = length(d);
    return {{.origin = origin, .direction = d / distance, .shadow = true}, distance};
}

// Through glass the light is tinted at each crossing (shadowFilter) and absorbed inside, along
// the straight line: Whitted's model has no caustics. Opaque scenes take the any-hit query alone.
// Every ray here, the walk's included, is a shadow ray: single-sided surfaces block it where the
// light sees their front (render/material_filter.h).
Color Tracer::transmittance(const ShadowRay& shadow, RenderCounters& counters) const {
    constexpr Color kClear{1, 1, 1};
    if (!anyGlass_) return passed(accel_.occluded(shadow.ray, shadow.distance, counters.shadow));
    Ray ray = shadow.ray;
    Real distance = shadow.distance;
    // Each crossing starts past the last surface; the cap keeps a ray along a pathological
    // stack of coincident glass surfaces finite (and takes the light as blocked there).
    constexpr int kMaxCrossings = 64;
    Color through = kClear;
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
        Hit hit;
        if (!accel_.intersect(ray, distance, hit, counters.shadow)) return through;
        const Transmission& t = context_.scene.materialOf(hit.prim).transmission;
        if (!t.passesLight()) return {};
        const Vec3 p = ray.at(hit.t);
        const Vec3 n = context_.scene.primitives.normal(hit.prim, p);
        const Real cosine = dot(n, ray.direction);  // > 0: the ray leaves the volume
        through = through * shadowFilter(t, std::abs(cosine));
        if (cosine > 0 && t.absorbs()) through = through * absorbed(t, hit.t);
        if (through == Color{}) return through;
        distance -= hit.t;
        ray.origin = p + n * (cosine > 0 ? epsilon_ : -epsilon_);
    }
    return {};
}

RayDifferential Tracer::secondary(const Vec3& d, Real cone, float widen) const {
    return filtered_ ? RayDifferential::cone(d, cone, coneSpread_ + Real(widen)) : RayDifferential{};
}

Color Tracer::reflection(const SurfacePoint& s, const Vec3& dir, const Material& m, int depth, bool inBundle,
                         SampleRng& rng, RenderCounters& counters, Real cone) const {
    const Vec3 origin = s.point + s.geometricNormal * epsilon_;
    Vec3 r = mirror(dir, s.shadingNormal);
    // keepReflectionAbove keeps r out of the surface but for rounding at grazing incidence
    if (dot(r, s.geometricNormal) <= 0) r = mirror(r, s.geometricNormal);
    return lobe({origin, r}, s.geometricNormal, m, s, true, depth, inBundle, rng, counters, cone);
}

Color Tracer::lobe(const Ray& axis, const Vec3& side, const Material& m, const SurfacePoint& s, bool rough, int depth,
                   bool inBundle, SampleRng& rng, RenderCounters& counters, Real cone) const {
    const auto spread = [&] { return rough ? glossySpread(context_, m, s) : 0.0f; };
    const float sigma = settings_.glossyReflections ? spread() : 0;
    if (!(sigma > 0)) {
        ++counters.reflection.rays;
        Hit hit;
        if (!accel_.intersect(axis, kInfinity, hit, counters.reflection)) return background(axis.direction);
        // Its footprint widens instead, by a sigma read only for a ray that hits something.
        const float widen = 2 * (settings_.glossyReflections ? sigma : spread());
        return shadeHit(axis, hit, depth + 1, inBundle, rng, counters, secondary(axis.direction, cone, widen));
    }
    // Directions around the axis, offset in the plane across it by a 2-D normal distribution
    // with this sigma (about the angle in radians, for small sigmas).
    Vec3 t, b;
    orthonormalBasis(axis.direction, t, b);
    const int samples = inBundle ? 1 : settings_.distributedSamples;
    Color sum;
    for (int i = 0; i < samples; ++i) {
        Real g1, g2;
        rng.normalPair(g1, g2);
        Vec3 d = normalize(axis.direction + (t * g1 + b * g2) * Real(sigma));
        if (dot(d, side) <= 0) d = mirror(d, side);  // across the surface: fold it back
        ++counters.reflection.rays;
        sum += trace({axis.origin, d}, depth + 1, true, rng, counters, secondary(d, cone, 0));
    }
    return samples == 1 ? sum : sum * (1.0f / float(samples));
}

// The transmitted ray leaves from the far side of the surface, one epsilon through it; a rough
// surface spreads it as a glossy one does its reflection.
Color Tracer::transmitted(const SurfacePoint& s, const Material& m, float weight, const RefractionSplit& split,
                          int depth, bool inBundle, SampleRng& rng, RenderCounters& counters, Real cone) const {
    if (split.reflected >= 1) return {};  // total internal reflection
    const Transmission& t = m.transmission;
    const Ray through{s.point - s.geometricNormal * epsilon_, split.direction};
    return lobe(through, -s.geometricNormal, m, s, !t.thin, depth, inBundle, rng, counters, cone) * t.color *
           (weight * (1 - split.reflected));
}

}  // namespace rt
