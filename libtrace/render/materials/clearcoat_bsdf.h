// glTF's KHR_materials_clearcoat for the path tracer: a clear dielectric layer of ior 1.5 (F0 =
// 0.04) over the metallic-roughness BRDF, as car paint or varnished wood, mixed as the extension
// defines it:
//
//   f = weight F_c D V + (1 - weight F_c) f_base,   F_c = 0.04 + 0.96 (1 - wo.n)^5
//
// D V the GGX lobe of the coat's own roughness (alpha = roughness^2, render/materials/microfacet.h).
// The coat's Fresnel is taken at the normal from the viewer's side, as the Khronos sample viewer
// does, not per microfacet: the share the coat reflects is then exactly the share it takes from
// the base, and since D V reflects at most all of its light, a coat over a base that reflects at
// most all of its light does too (no energy is made, tests/unit/render_clearcoat_test.cpp).
//
// Sampling picks the coat's visible normals with probability weight * max(F_c, 1/4), else the
// base's own strategy; pdf() is the mixture's density, which MIS needs.
#pragma once

#include <optional>

#include "render/materials/lobe.h"
#include "render/materials/pbr_bsdf.h"

namespace rt {

class ClearcoatBsdf {
public:
    // `weight` (clearcoatFactor) and `roughness` (clearcoatRoughnessFactor) in [0, 1].
    ClearcoatBsdf(const PbrBsdf& base, float weight, float roughness);
    // the base's kinds: the coat adds a glossy reflection, which the base has already
    static constexpr BsdfFlags flags() { return PbrBsdf::flags(); }

    Color evaluate(const Vec3& wo, const Vec3& wi) const;
    Real pdf(const Vec3& wo, const Vec3& wi) const;
    std::optional<BsdfSample> sample(const Vec3& wo, Real u1, Real u2, Real u3) const;

private:
    Real coatFresnel(const Vec3& wo) const;  // weight F_c: the share of the light the coat reflects
    Real coatShare(const Vec3& wo) const;    // the probability sample() takes the coat
    Real coatPdf(const Vec3& wo, const Vec3& wi) const;

    PbrBsdf base_;
    Real weight_;
    Real alpha_;
};

}  // namespace rt
