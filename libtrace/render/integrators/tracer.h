// The Whitted ray tracer of thesis 2.1 and 3.3.4 (the thesis's Raytracer and DistributedRT):
// the colour of one pixel from camera rays, Phong shading with an ambient term, hard or
// soft shadows, mirror or glossy reflections, and refraction through glass (render/refraction.h).
//
// Distributed ray tracing (thesis 2.6.2) sends bundles of -r rays: shadow rays over a
// light's disc, reflection rays spread around the mirror direction by a 2-D normal
// distribution with the material's sigma. A bundle splits a path only once: the rays
// under a glossy bundle take one sample each, so the cost grows as r, not r^depth.
#pragma once

#include "accel/accelerator.h"
#include "render/camera_rays.h"
#include "render/film/aov.h"
#include "render/lights/environment_light.h"
#include "render/refraction.h"
#include "render/render_settings.h"
#include "render/render_stats.h"
#include "render/sampling.h"
#include "render/surface.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

class Tracer {
public:
    // The context's scene must be flattened and `accel` built over its primitives; both, and the
    // context's image lookups (none: image textures are white), must outlive the tracer.
    Tracer(const ShadingContext& context, const Accelerator& accel, const RenderSettings& settings);

    // The linear colour of pixel (x, y): the mean of its camera samples. A sample that comes
    // out NaN or infinite counts as black and is recorded in counters.nonFinite. `coverage`
    // is the fraction of the camera rays that hit something (alpha); `aovs`, if given, receives
    // the pixel's AOVs.
    Color pixel(int x, int y, RenderCounters& counters, float& coverage, PixelAovs* aovs = nullptr) const;
    Color pixel(int x, int y, RenderCounters& counters) const {
        float coverage;
        return pixel(x, y, counters, coverage);
    }

    // Whether pixelRun may trace this render's pixels: --packets on, one camera ray through each
    // pixel's centre (-S 1), and no AOVs (their cost layers count each camera ray's own work).
    bool tracesPackets() const;
    // Pixels (x0, y) to (x0 + count - 1, y), count <= kPacketSize, of a render tracesPackets():
    // the first hits of their camera rays found by one Accelerator::intersectPacket, the shadow
    // rays from those hits to each light with one (traceShadowPackets) by one occludedPacket per
    // light, each pixel then shaded exactly as pixel() shades it (the same bits and counters).
    void pixelRun(int x0, int y, int count, RenderCounters& counters, Color* colors, float* coverages) const;

    // The colour seen along a ray that has already been reflected `depth` times; `differential`
    // sets the footprint of its texture lookups (render/ray_differential.h; none: unfiltered).
    Color trace(const Ray& ray, int depth, bool inBundle, SampleRng& rng, RenderCounters& counters,
                const RayDifferential& differential = {}) const;

    // How far secondary rays start off a surface: scaled to the scene's size (see the .cpp).
    Real epsilon() const { return epsilon_; }

private:
    // A shadow ray and how far it goes: to the light, or kInfinity to a directional one.
    struct ShadowRay {
        Ray ray;
        Real distance;
    };
    // The lights whose shadow rays pixelRun traces as packets: the first kPacketLights, at most,
    // so that what it found fits in a PacketShadows.
    static constexpr std::size_t kPacketLights = 16;
    // What pixelRun's shadow packets found at one pixel's camera hit, for shade() at depth 0: bit
    // l of `traced`, whether light l's shadow ray was traced, and of `blocked`, whether it was blocked.
    struct PacketShadows {
        std::uint32_t traced = 0, blocked = 0;

        bool has(std::size_t light) const { return light < kPacketLights && (traced >> light) & 1u; }
        bool isBlocked(std::size_t light) const { return (blocked >> light) & 1u; }
    };
    // The surface a camera ray sees at its first hit, and the radius of the ray's footprint there.
    struct CameraHit {
        SurfacePoint surface;
        Real cone;
    };

    // The camera ray `ray` through image position (px, py) at its first hit `hit`.
    CameraHit cameraHit(Real px, Real py, const Ray& ray, const Hit& hit) const;
    // The sample of the camera ray `ray` through image position (px, py), whose first hit is
    // `hit` (none: it sees the background); `aovSums`, if given, receives the hit's AOVs.
    Color cameraSample(Real px, Real py, const Ray& ray, const Hit* hit, SampleRng& rng, RenderCounters& counters,
                       AovSums* aovSums) const;
    // The colour at `s`, the surface of `hit` (surfaceAt); `cone`: the radius of the ray's
    // footprint there, which the reflected and transmitted rays widen from. `known`, if given,
    // holds the visibility of the lights whose shadow rays pixelRun has traced already.
    Color shade(const Ray& ray, const Hit& hit, const SurfacePoint& s, int depth, bool inBundle, SampleRng& rng,
                RenderCounters& counters, Real cone, const PacketShadows* known = nullptr) const;
    // The shadow rays of a run's camera hits (`surfaces` where found[i]), one occludedPacket per
    // light among the first kPacketLights whose visibility is one ray, as visibility() would trace
    // them one by one: for the pixels shade() traces one for, counted alike.
    void traceShadowPackets(const SurfacePoint* surfaces, const bool* found, int count, PacketShadows* shadows,
                            RenderCounters& counters) const;
    // Fraction of `light` seen from the surface (1 without shadows), tinted by glass in the way;
    // toLight: unit, towards it.
    Color visibility(const SurfacePoint& s, const Light& light, const Vec3& toLight, bool inBundle, SampleRng& rng,
                     RenderCounters& counters) const;
    Color reflection(const SurfacePoint& s, const Vec3& dir, const Material& m, int depth, bool inBundle,
                     SampleRng& rng, RenderCounters& counters, Real cone) const;
    // What comes along `axis` from the glossy lobe of material m at s, of width sigma
    // (glossySpread; 0 unless `rough`), on the side `side` faces: with distributed ray tracing
    // the mean of a bundle of rays jittered around it (thesis 2.6.2), else the one ray, whose
    // texture footprint widens by 2 sigma instead. sigma may take a texture lookup: the one
    // ray reads it only if it hits something.
    Color lobe(const Ray& axis, const Vec3& side, const Material& m, const SurfacePoint& s, bool rough, int depth,
               bool inBundle, SampleRng& rng, RenderCounters& counters, Real cone) const;
    // The colour of `hit`, found by `ray`, whose footprint is `differential`.
    Color shadeHit(const Ray& ray, const Hit& hit, int depth, bool inBundle, SampleRng& rng, RenderCounters& counters,
                   const RayDifferential& differential) const;
    // Whether visibility() samples `light` over its disc (soft shadows) with random rays; else it
    // traces the one ray shadowRay() gives, which pixelRun may trace in a packet.
    bool sampledOverArea(const Light& light) const;
    // Where shadow rays from `s` start: off the surface, on the side the incoming ray came from.
    Vec3 shadowOrigin(const SurfacePoint& s) const { return s.shadowOrigin + s.geometricNormal * epsilon_; }
    // The one shadow ray from `s` to a light not sampledOverArea, whose direction is toLight.
    ShadowRay shadowRay(const SurfacePoint& s, const Light& light, const Vec3& toLight) const;
    // The shadow ray from `origin` to the point `target`.
    static ShadowRay towards(const Vec3& origin, const Vec3& target);
    // What `shadow` lets through: black when blocked.
    Color transmittance(const ShadowRay& shadow, RenderCounters& counters) const;
    // The colour the transmitted ray of `split` brings through material m, whose transmission is
    // `weight` there (transmissionAt), weighted (render/refraction.h); a rough glass spreads it as
    // a glossy surface its reflection (lobe).
    Color transmitted(const SurfacePoint& s, const Material& m, float weight, const RefractionSplit& split, int depth,
                      bool inBundle, SampleRng& rng, RenderCounters& counters, Real cone) const;
    // The differential of a ray leaving a surface along `d` where the footprint's radius is
    // `cone`: a cone widening by the pixel angle plus `widen` radians per unit distance.
    RayDifferential secondary(const Vec3& d, Real cone, float widen) const;
    // What a ray that leaves the scene along `direction` sees: the environment image
    // (--environment), as glTF viewers show it behind the model and in its reflections and
    // refractions, else the background colour. It lights nothing here (the path tracer's does).
    Color background(const Vec3& direction) const { return environment_.radiance(direction); }

    ShadingContext context_;  // the scene and its image lookups
    const Accelerator& accel_;
    RenderSettings settings_;
    CameraRays camera_;
    EnvironmentLight environment_;
    Color ambientLight_;
    Real epsilon_;
    // The camera's differentials are scaled by this (fewer pixel samples: wider), and ray cones
    // widen by this per unit distance: render/ray_differential.h.
    Real differentialScale_;
    Real coneSpread_;
    bool anyGlass_ = false;  // a material lets light through: shadow rays must look past hits
    bool filtered_ = false;  // image textures are read: rays carry differentials
};

}  // namespace rt
