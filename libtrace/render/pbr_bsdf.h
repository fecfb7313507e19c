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

// The GGX distribution of normals and Smith's masking, for tests and the BRDF.
Real ggxD(const Vec3& h, Real alpha);
Real smithLambda(const Vec3& w, Real alpha);

struct BsdfSample {
    Vec3 wi;
    Color weight;  // f cos / pdf
    Real pdf = 0;
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
    Color multipleScattering(const Vec3& wo, const Vec3& wi) const;

    PbrParameters p_;
    Real alpha_;
    Real averageAlbedo_;               // E_avg of the GGX lobe at this roughness
    Color multipleScatteringFresnel_;  // F_ms, per channel
};

}  // namespace rt
