#include "render/integrators/path_tracer.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "render/film/pixel_estimate.h"
#include "render/lights/light_sample.h"
#include "render/materials/material.h"
#include "render/normal_map.h"
#include "render/refraction.h"

namespace rt {

namespace {

// Russian roulette starts after this many bounces, and never ends a path with a higher
// probability than 1 - kMinSurvival (pbrt-v4 does the same).
constexpr int kRouletteBounces = 3;
constexpr Real kMinSurvival = Real(0.05);

// Veach's power heuristic (beta = 2) for one sample of each strategy.
Real powerHeuristic(Real pdf, Real otherPdf) {
    const Real a = pdf * pdf, b = otherPdf * otherPdf;
    return a + b > 0 ? a / (a + b) : 0;
}

float maxComponent(const Color& c) { return std::max({c.r, c.g, c.b}); }

// The frame of the shading normal, unless the viewer is below it (after keepReflectionAbove only
// a shading normal turned below the surface can be): then the geometric normal's.
ShadingFrame shadingFrame(const SurfacePoint& s, const Vec3& toViewer) {
    return ShadingFrame(dot(toViewer, s.shadingNormal) > 0 ? s.shadingNormal : s.geometricNormal);
}

}  // namespace

PathTracer::PathTracer(const ShadingContext& context, const Accelerator& accel, const RenderSettings& settings)
    : context_(context),
      accel_(accel),
      settings_(settings),
      camera_(context.scene.camera, settings.width, settings.height),
      lights_(context, settings.lightSampler),
      epsilon_(secondaryRayOffset(context.scene.primitives)) {}

Color PathTracer::pixel(int x, int y, RenderCounters& counters, float& coverage, PixelAovs* aovs) const {
    PixelEstimate estimate;
    AovSums aovSums;
    for (int i = 0; i < settings_.pixelSamples; ++i) {
        bool seen = false;
        const Color c = sample(x, y, i, counters, seen, aovs ? &aovSums : nullptr);  // before add() reads `seen`
        if (!estimate.add(c, seen)) counters.nonFinite.add(x, y);
    }
    coverage = estimate.coverage();
    if (aovs) *aovs = aovSums.mean(estimate.varianceOfMean());
    return estimate.mean();
}

Color PathTracer::sample(int x, int y, int index, RenderCounters& counters, bool& seen, AovSums* aovs) const {
    const std::optional<RenderCounters> before = aovs ? std::optional(counters) : std::nullopt;
    SobolSampler sampler{std::uint32_t(x), std::uint32_t(y), std::uint32_t(index), settings_.seed};
    const auto [sx, sy] = sampler.next2D();  // a box filter over the pixel
    ++counters.camera.rays;
    const Color c = radiance(camera_.at(Real(x) + sx, Real(y) + sy), sampler, counters, seen, aovs);
    if (aovs) aovs->finishSample(*before, counters);
    return c;
}

Color PathTracer::radiance(const Ray& cameraRay, SobolSampler& sampler, RenderCounters& counters, bool& seen,
                           AovSums* aovs) const {
    Color result, throughput{1, 1, 1};
    Ray ray = cameraRay;
    // How `ray` was sampled, for MIS at the emitter it hits: the BSDF's density, and whether a
    // light sample could have found the same direction (not through glass, not a delta lobe).
    Real bsdfPdf = 0;
    bool lightSampled = false;
    LightQuery from;  // where `ray` left, as next-event estimation there saw it
    // lightPdf() is only asked for when it matters (a light tree's walk is not free)
    const auto misWeight = [&](const auto& lightPdf) {
        return lightSampled ? powerHeuristic(bsdfPdf, lightPdf()) : Real(1);
    };
    seen = false;
    for (int bounce = 0;; ++bounce) {
        Hit hit;
        if (!accel_.intersect(ray, kInfinity, hit, bounce == 0 ? counters.camera : counters.reflection)) {
            const Color sky = lights_.environment().radiance(ray.direction);
            if (bounce == 0) return sky;
            result += clampIndirect(
                throughput * sky * float(misWeight([&] { return lights_.pdfEnvironment(ray.direction); })), bounce);
            break;
        }
        seen = seen || bounce == 0;
        const SurfacePoint s = shadedSurfaceAt(context_, ray, hit);
        const Material& m = context_.scene.materialOf(hit.prim);
        if (aovs && bounce == 0) aovs->addHit(context_.scene, s, hit, surfaceColor(context_, m, s));
        // Beer-Lambert along the stretch just travelled inside (render/refraction.h)
        if (!s.frontFace && m.transmission.absorbs()) throughput = throughput * absorbed(m.transmission, hit.t);
        if (const Color emitted = emission(m, s, ray, hit); emitted != Color{}) {
            const Real weight =
                misWeight([&] { return lights_.pdfTriangle(hit.prim, from.point, from.normal, ray.direction, hit.t); });
            result += clampIndirect(throughput * emitted * float(weight), bounce);
        }
        if (bounce == settings_.maxBounces) break;

        // the numbers in a fixed order, so that every material draws the same dimensions
        const Real pick = sampler.next1D();
        const auto [l1, l2] = sampler.next2D();
        Real lobe = sampler.next1D();
        const auto [u1, u2] = sampler.next2D();
        const Vec3 toViewer = -ray.direction;
        const ShadingFrame frame = shadingFrame(s, toViewer);
        const Vec3 wo = frame.toLocal(toViewer);
        const Bsdf bsdf = bsdfAt(context_, m, s, lobe);
        from = {s.shadowOrigin + s.geometricNormal * epsilon_, s.geometricNormal};
        if (isNonSpecular(bsdf.flags()))
            result +=
                clampIndirect(throughput * directLight(from, bsdf, frame, wo, {pick, l1, l2}, counters), bounce + 1);

        const std::optional<BsdfSample> next = bsdf.sample(wo, lobe, u1, u2);
        if (!next) break;
        const Vec3 wi = frame.toWorld(next->wi);
        const bool through = next->wi.z < 0;
        if ((dot(wi, s.geometricNormal) > 0) == through) break;  // on the wrong side of the true surface
        throughput = throughput * next->weight;
        bsdfPdf = next->pdf;
        lightSampled = !next->specular && !through;
        ray = {s.point + s.geometricNormal * (through ? -epsilon_ : epsilon_), wi};
        ++counters.reflection.rays;

        if (bounce + 1 >= kRouletteBounces) {
            const Real survival = std::clamp(Real(maxComponent(throughput)), kMinSurvival, Real(1));
            if (sampler.next1D() >= survival) break;
            throughput = throughput * float(1 / survival);
        }
    }
    return result;
}

Color PathTracer::directLight(const LightQuery& at, const Bsdf& bsdf, const ShadingFrame& frame, const Vec3& wo,
                              const LightNumbers& u, RenderCounters& counters) const {
    if (lights_.empty()) return {};
    const Vec3& origin = at.point;
    const std::optional<LightSample> light = lights_.sample(origin, at.normal, u.pick, u.u1, u.u2);
    if (!light || dot(light->direction, at.normal) <= 0) return {};
    const Vec3 wi = frame.toLocal(light->direction);
    const Color f = bsdf.evaluate(wo, wi);
    if (f == Color{}) return {};
    const Color arriving = lightRadiance(*light, origin);
    if (arriving == Color{}) return {};
    // the shadow ray stops short of an area light's own surface
    const Real tMax =
        light->source == LightSample::Source::Triangle ? light->distance * (1 - Real(1e-4)) : light->distance;
    // A shadow ray to one of the scene's lights (point, spot, directional) meets single-sided
    // surfaces as the light sees them, as in the Whitted tracer (render/material_filter.h).
    // Emitters and the environment are found by the BSDF's rays too, which see surfaces from
    // their origin; the shadow rays to them keep that rule, so that both strategies MIS weighs
    // see the same scene.
    const Ray shadowRay{.origin = origin, .direction = light->direction, .shadow = light->delta()};
    ++counters.shadow.rays;
    if (accel_.occluded(shadowRay, tMax, counters.shadow)) return {};
    const Real weight = light->delta() ? 1 : powerHeuristic(light->pdf, bsdf.pdf(wo, wi));
    return f * arriving * float(weight / light->pdf);
}

// Emitters shine from their front (a triangle's winding, a sphere's outside) only: a light
// panel under a ceiling would otherwise also fill the gap above it, which paths find rarely
// and then bring back as fireflies. (The Whitted tracer shows emission from both sides.)
Color PathTracer::emission(const Material& m, const SurfacePoint& s, const Ray& ray, const Hit& hit) const {
    if (m.emission.color == Color{} || dot(context_.scene.primitives.normal(hit.prim, s.point), ray.direction) >= 0)
        return {};
    return surfaceEmission(context_, m, s);
}

Color PathTracer::lightRadiance(const LightSample& light, const Vec3& from) const {
    switch (light.source) {
        case LightSample::Source::Point:  // with the light's falloff and cone, as the Whitted tracer lights
            return lightIncidence(context_.scene.lights[light.index], from).color;
        case LightSample::Source::Triangle: {
            const Ray toLight{from, light.direction};
            const Hit there{light.distance, light.index, light.b1, light.b2};
            return surfaceEmission(context_, context_.scene.materialOf(light.index),
                                   surfaceAt(context_.scene.primitives, toLight, there));
        }
        case LightSample::Source::Environment:
            return lights_.environment().radiance(light.direction);
    }
    return {};
}

// `interactions`: how many surfaces the light has met on its way to the camera; from two on it
// is indirect light, which --clamp caps (a biased cure for fireflies, off by default).
Color PathTracer::clampIndirect(const Color& c, int interactions) const {
    if (settings_.clampRadiance <= 0 || interactions < 2) return c;
    const float peak = maxComponent(c);
    return peak > settings_.clampRadiance ? c * (settings_.clampRadiance / peak) : c;
}

}  // namespace rt
