// The path tracer's glass: KHR_materials_transmission, _ior and _volume as a rough dielectric
// (Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces"): a GGX lobe of
// microfacets that each reflect or refract the light by Fresnel, sampled by their visible
// normals (Heitz 2018) as pbrt-v4's DielectricBxDF does. A smooth surface (roughness below 0.03)
// is a delta: the mirror direction or Snell's, nothing in between. A thin-walled material
// (Transmission::thin: glTF without a volume) lets the light through without bending: its
// transmitted lobe is the reflected one mirrored through the surface, as the glTF specification
// describes it. The material data and Snell's law are the Whitted tracer's (scene/transmission.h,
// render/refraction.h); the absorption inside is the path tracer's, along the path's length.
//
// Directions are in the local frame of the shading normal on the side light leaves towards the
// viewer (wo.z > 0); a transmitted direction has wi.z < 0. Radiance crossing into the other side
// is scaled by (n_this / n_other)^2 (pbrt's TransportMode::Radiance), which cancels on the way out.
#pragma once

#include <optional>

#include "render/materials/lobe.h"
#include "scene/transmission.h"

namespace rt {

class DielectricBsdf {
public:
    // `entering`: wo is on the outside (the side the surface's normal faces); `roughness`: glTF's.
    DielectricBsdf(const Transmission& t, float roughness, bool entering);

    // f(wo, wi) |cos(wi)|; zero for a smooth surface (a delta: sample() alone finds it).
    Color evaluate(const Vec3& wo, const Vec3& wi) const;
    Real pdf(const Vec3& wo, const Vec3& wi) const;
    // u1 chooses reflection or transmission by Fresnel, (u2, u3) the microfacet.
    std::optional<BsdfSample> sample(const Vec3& wo, Real u1, Real u2, Real u3) const;
    BsdfFlags flags() const {
        return BsdfFlags::Reflection | BsdfFlags::Transmission | (smooth_ ? BsdfFlags::Specular : BsdfFlags::Glossy);
    }

private:
    // Schlick's reflectance at a facet seen at cosine c from wo's side (1: total internal reflection).
    Real fresnel(Real c) const;
    // The facet normal that turns wo into wi (h.z >= 0), and whether wi is reflected; none if degenerate.
    std::optional<Vec3> halfVector(const Vec3& wo, const Vec3& wi) const;
    Real visibleNormalPdf(const Vec3& wo, const Vec3& h) const;
    std::optional<BsdfSample> sampleSmooth(const Vec3& wo, Real u1) const;

    Color tint_;  // Transmission::color: the transmitted light's colour
    float f0_;    // Schlick's reflectance at normal incidence, from the ior
    Real eta_;    // n_other / n_this: the index ratio wi sees crossing (1 when thin)
    Real alpha_;
    bool thin_;
    bool smooth_;
};

}  // namespace rt
