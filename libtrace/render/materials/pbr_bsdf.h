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

#include "render/materials/lobe.h"
#include "scene/metallic_roughness.h"

namespace rt {

class PbrBsdf {
public:
    PbrBsdf(const Color& baseColor, const MetallicRoughness& factors);

    // f(wo, wi) cos(wi): zero when either lies below the surface.
    Color evaluate(const Vec3& wo, const Vec3& wi) const;
    Real pdf(const Vec3& wo, const Vec3& wi) const;
    // A direction for u1 (picks the lobe) and u2, u3 (the direction); none when it falls below.
    std::optional<BsdfSample> sample(const Vec3& wo, Real u1, Real u2, Real u3) const;
    static constexpr BsdfFlags flags() { return BsdfFlags::Reflection | BsdfFlags::Diffuse | BsdfFlags::Glossy; }

private:
    // What evaluate and pdf both need for a pair of directions above the surface, computed once
    // per pair: sample() asks for both, and each costs a normalisation, D, Smith's Lambda at wo
    // (a square root) and, for metals, a lookup of the albedo table at wo.
    struct Pair {
        Vec3 h;            // the half vector
        Real d;            // GGX's D(h)
        Real lambdaO;      // Smith's Lambda(wo)
        Real albedoO = 0;  // E(wo), metals only (0 otherwise, unused)
    };
    Pair pair(const Vec3& wo, const Vec3& wi, Real albedoO) const;
    Real albedoAt(const Vec3& wo) const;  // E(wo) for metals, else 0
    Color evaluate(const Vec3& wo, const Vec3& wi, const Pair& p) const;
    Real pdf(const Vec3& wo, const Vec3& wi, Real glossyShare, const Pair& p) const;
    Real glossyProbability(const Vec3& wo, Real albedoO) const;
    Color multipleScattering(const Vec3& wi, Real albedoO) const;

    Color base_;
    MetallicRoughness f_;
    Real alpha_;
    Real averageAlbedo_;               // E_avg of the GGX lobe at this roughness
    Color multipleScatteringFresnel_;  // F_ms, per channel
};

}  // namespace rt
