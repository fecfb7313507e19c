// The path tracer beside the thesis's Whitted tracer (rt-render --integrator path; the thesis's
// chapter 5 proposes its ray tracer as the base for one). Unidirectional path tracing with
// next-event estimation, combined with the BSDF's own samples by multiple importance sampling
// with the power heuristic (Veach 1997, ch. 9); Russian roulette after three bounces; the glTF
// metallic-roughness BRDF (render/pbr_bsdf.h) and glass (render/dielectric_bsdf.h) with Beer-Lambert
// absorption; the sky a colour or an image (render/environment_light.h); per-pixel Owen-scrambled Sobol samples
// (render/sobol_sampler.h), so the image has the same bits for any thread count or region split.
// docs/path-tracing.md describes the model, the rule for thesis materials and the validation.
#pragma once

#include <variant>

#include "accel/accelerator.h"
#include "render/aov.h"
#include "render/camera_rays.h"
#include "render/dielectric_bsdf.h"
#include "render/light_distribution.h"
#include "render/pbr_bsdf.h"
#include "render/render_settings.h"
#include "render/render_stats.h"
#include "render/sampling.h"
#include "render/sobol_sampler.h"
#include "render/surface.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

// The BRDF parameters of material m whose colour at the point is `color`: its own
// metallic-roughness factors, or for a thesis (Phong) material: metallic = reflection,
// roughness from the mirror's spread or the Phong exponent, no specular layer when k_s = 0.
PbrParameters pbrParametersOf(const Material& m, const Color& color);

// The BSDF's local frame at a surface point: tangent, bitangent, normal (its z).
struct ShadingFrame {
    Vec3 axes[3];

    explicit ShadingFrame(const Vec3& n) {
        orthonormalBasis(n, axes[0], axes[1]);
        axes[2] = n;
    }
    Vec3 toLocal(const Vec3& v) const { return {dot(v, axes[0]), dot(v, axes[1]), dot(v, axes[2])}; }
    Vec3 toWorld(const Vec3& v) const { return axes[0] * v.x + axes[1] * v.y + axes[2] * v.z; }
};

// The BSDF at a hit: a transmissive material (Material::transmission, weight w at the hit:
// transmissionAt()) is glass (render/dielectric_bsdf.h) for a share w of its paths and the metallic-roughness BRDF for
// the rest; `lobe`, a uniform number, makes the choice and is stretched back to [0, 1) for sample().
class SurfaceBsdf {
public:
    SurfaceBsdf(const Material& m, const PbrParameters& p, float transmission, bool frontFace, Real& lobe);
    Color evaluate(const Vec3& wo, const Vec3& wi) const {
        return std::visit([&](const auto& b) { return b.evaluate(wo, wi); }, bsdf_);
    }
    Real pdf(const Vec3& wo, const Vec3& wi) const {
        return std::visit([&](const auto& b) { return b.pdf(wo, wi); }, bsdf_);
    }
    std::optional<BsdfSample> sample(const Vec3& wo, Real u1, Real u2, Real u3) const {
        return std::visit([&](const auto& b) { return b.sample(wo, u1, u2, u3); }, bsdf_);
    }
    // a delta lobe only: light samples find nothing it reflects
    bool smooth() const {
        return std::holds_alternative<DielectricBsdf>(bsdf_) && std::get<DielectricBsdf>(bsdf_).smooth();
    }

private:
    static std::variant<PbrBsdf, DielectricBsdf> choose(const Material& m, const PbrParameters& p, float glass,
                                                        bool frontFace, Real& lobe);
    std::variant<PbrBsdf, DielectricBsdf> bsdf_;
};

class PathTracer {
public:
    // As Tracer: the scene flattened, `accel` built over it; all three outlive the tracer.
    PathTracer(const Scene& scene, const Accelerator& accel, const RenderSettings& settings,
               const ImageTextures* images = nullptr);

    // The mean of the pixel's -S paths; coverage is the fraction whose camera ray hit something;
    // `aovs`, if given, receives the pixel's AOVs (render/aov.h). Non-finite samples count as
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
    // Light from one next-event sample at s, weighted against the BSDF's density.
    Color directLight(const SurfacePoint& s, const SurfaceBsdf& bsdf, const ShadingFrame& frame, const Vec3& wo,
                      const LightNumbers& u, RenderCounters& counters) const;
    // The BRDF's parameters at s: the material's, its metallic-roughness texture applied.
    PbrParameters pbrParametersAt(const Material& m, const SurfacePoint& s) const;
    Color emission(const Material& m, const SurfacePoint& s, const Ray& ray, const Hit& hit) const;
    Color lightRadiance(const LightSample& light, const Vec3& from) const;
    Color clampIndirect(const Color& c, int bounce) const;

    const Scene& scene_;
    const Accelerator& accel_;
    RenderSettings settings_;
    CameraRays camera_;
    LightDistribution lights_;
    Real epsilon_;
    const ImageTextures* images_;
};

}  // namespace rt
