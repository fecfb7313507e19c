// The path tracer beside the thesis's Whitted tracer (rt-render --integrator path; the thesis's
// chapter 5 proposes its ray tracer as the base for one). Unidirectional path tracing with
// next-event estimation, combined with the BSDF's own samples by multiple importance sampling
// with the power heuristic (Veach 1997, ch. 9); Russian roulette after three bounces; the BSDFs of
// render/materials/ (bsdfAt: the glTF metallic-roughness BRDF, glass) with Beer-Lambert absorption; the sky a colour or
// an image (render/lights/environment_light.h); per-pixel Owen-scrambled Sobol samples (render/sobol_sampler.h), so the
// image has the same bits for any thread count or region split. docs/path-tracing.md describes the model, the rule for
// thesis materials and the validation.
#pragma once

#include "accel/accelerator.h"
#include "render/camera_rays.h"
#include "render/film/aov.h"
#include "render/lights/light_distribution.h"
#include "render/materials/bsdf.h"
#include "render/render_settings.h"
#include "render/render_stats.h"
#include "render/sampling.h"
#include "render/sobol_sampler.h"
#include "render/surface.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

class PathTracer {
public:
    // As Tracer: the scene flattened, `accel` built over it; all three outlive the tracer.
    PathTracer(const ShadingContext& context, const Accelerator& accel, const RenderSettings& settings);

    // The mean of the pixel's -S paths; coverage is the fraction whose camera ray hit something;
    // `aovs`, if given, receives the pixel's AOVs (render/film/aov.h). Non-finite samples count as
    // black and are recorded in counters.nonFinite.
    Color pixel(int x, int y, RenderCounters& counters, float& coverage, PixelAovs* aovs = nullptr) const;

    // Path `index` of pixel (x, y), as pixel() takes it (possibly non-finite); `seen` tells whether
    // its camera ray hit anything; `aovs`, if given, receives what it hit and the path's work.
    // The progressive renderer (render/renderer.h) takes one per pass.
    Color sample(int x, int y, int index, RenderCounters& counters, bool& seen, AovSums* aovs = nullptr) const;

    // The radiance arriving along a camera ray; `seen` tells whether it hit anything, `aovs` what.
    Color radiance(const Ray& ray, SobolSampler& sampler, RenderCounters& counters, bool& seen,
                   AovSums* aovs = nullptr) const;

private:
    struct LightNumbers {
        Real pick, u1, u2;  // which light, and where on it
    };
    // Where next-event estimation samples a light from: the shadow rays' origin, off the surface,
    // and the geometric normal on the viewer's side. Kept for the MIS weight of the emitter the
    // BSDF's ray from there hits, whose light-sampling density depends on both (a light tree's).
    struct LightQuery {
        Vec3 point, normal;
    };
    // Light from one next-event sample at `at`, weighted against the BSDF's density.
    Color directLight(const LightQuery& at, const Bsdf& bsdf, const ShadingFrame& frame, const Vec3& wo,
                      const LightNumbers& u, RenderCounters& counters) const;
    Color emission(const Material& m, const SurfacePoint& s, const Ray& ray, const Hit& hit) const;
    Color lightRadiance(const LightSample& light, const Vec3& from) const;
    Color clampIndirect(const Color& c, int bounce) const;

    ShadingContext context_;  // the scene and its image lookups
    const Accelerator& accel_;
    RenderSettings settings_;
    CameraRays camera_;
    LightDistribution lights_;
    Real epsilon_;
};

}  // namespace rt
