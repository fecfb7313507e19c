// The Trowbridge-Reitz (GGX) microfacet distribution the path tracer's glossy lobes share
// (render/materials/pbr_bsdf.h, dielectric_bsdf.h, clearcoat_bsdf.h): its normals, Smith's
// masking, the sampling of visible normals and Schlick's Fresnel weight. Directions are in the
// local frame, z up; D and Lambda depend on |z| only.
#pragma once

#include "core/vec3.h"

namespace rt {

// Below this alpha the lobe is a mirror for every practical purpose, and D's peak would
// overflow float; glTF's roughness 0 renders as alpha 1e-3 (roughness 0.03).
inline constexpr Real kMinAlpha = Real(1e-3);
// The reflectance at normal incidence of a dielectric of ior 1.5: ((1.5 - 1) / (1.5 + 1))^2.
inline constexpr float kDielectricF0 = 0.04f;

Real ggxD(const Vec3& h, Real alpha);
Real smithLambda(const Vec3& w, Real alpha);
Real smithG1(const Vec3& w, Real alpha);
// A microfacet normal seen from wo (wo.z > 0), sampled with density G1(wo) max(0, wo.h) D(h) / wo.z
// (Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)); (u1, u2) in [0, 1)^2.
Vec3 sampleVisibleNormal(const Vec3& wo, Real alpha, Real u1, Real u2);
// Schlick's (1 - cos)^5, the weight of 1 - F0 in his Fresnel approximation.
Real schlickWeight(Real cosine);

}  // namespace rt
