// The glTF 2.0 metallic-roughness BRDF as the specification's appendix B defines it, for the
// path tracer: a Trowbridge-Reitz (GGX) microfacet lobe with height-correlated Smith
// masking-shadowing, Schlick's Fresnel, and a Lambertian base, mixed by metallic:
//
//   f = (1 - metallic) * [(1 - F_d) * base / pi + F_d * D V] + metallic * F_m * D V
//   F_d = specular * (0.04 + 0.96 (1 - |v.h|)^5)   (ior 1.5; specular: KHR_materials_specular)
//   F_m = base + (1 - base) (1 - |v.h|)^5
//   D V = D(h) G2(v, l) / (4 |n.v| |n.l|),  alpha = roughness^2
//
// plus, for metals, Kulla and Conty's (2017) multiple-scattering lobe, which gives back the energy
// single-scattering GGX loses between microfacets (a white metal reflects all the light it gets).
//
// Directions are in the local frame of the shading normal (z up). Sampling picks the glossy or
// the diffuse lobe by their estimated reflectance, then the glossy lobe's visible normals (Heitz
// 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)) or a cosine-weighted
// direction; pdf() is the density of that combined strategy, which MIS needs.
#pragma once

#include <optional>

#include "core/color.h"
#include "core/vec3.h"

namespace rt {

struct PbrParameters {
    Color baseColor{1, 1, 1};
    float metallic = 0;
    float roughness = 1;
    float specular = 1;  // KHR_materials_specular's specularFactor: 0 leaves a pure Lambertian base
};

// The GGX distribution of normals and Smith's masking, for tests and the BSDFs (this one and
// render/dielectric_bsdf.h). Directions in the local frame, z up; both depend on |z| only.
Real ggxD(const Vec3& h, Real alpha);
Real smithLambda(const Vec3& w, Real alpha);
Real smithG1(const Vec3& w, Real alpha);
// A microfacet normal seen from wo (wo.z > 0), sampled with density G1(wo) max(0, wo.h) D(h) / wo.z
// (Heitz 2018); (u1, u2) in [0, 1)^2.
Vec3 sampleVisibleNormal(const Vec3& wo, Real alpha, Real u1, Real u2);

struct BsdfSample {
    Vec3 wi;
    Color weight;  // f cos / pdf (for a specular direction: its share of the light)
    Real pdf = 0;
    bool specular = false;  // a delta direction: no light sample could have found it
};

class PbrBsdf {
public:
    explicit PbrBsdf(const PbrParameters& p);

    // f(wo, wi) cos(wi): zero when either lies below the surface.
    Color evaluate(const Vec3& wo, const Vec3& wi) const;
    Real pdf(const Vec3& wo, const Vec3& wi) const;
    // A direction for u1 (picks the lobe) and u2, u3 (the direction); none when it falls below.
    std::optional<BsdfSample> sample(const Vec3& wo, Real u1, Real u2, Real u3) const;

private:
    Real glossyProbability(const Vec3& wo) const;
    Real pdf(const Vec3& wo, const Vec3& wi, Real glossyShare) const;
    Color multipleScattering(const Vec3& wo, const Vec3& wi) const;

    PbrParameters p_;
    Real alpha_;
    Real averageAlbedo_;               // E_avg of the GGX lobe at this roughness
    Color multipleScatteringFresnel_;  // F_ms, per channel
};

}  // namespace rt
