#include "render/materials/dielectric_bsdf.h"

#include <algorithm>
#include <cmath>

#include "render/materials/microfacet.h"
#include "render/refraction.h"

namespace rt {

namespace {

Vec3 flipZ(const Vec3& w) { return {w.x, w.y, -w.z}; }
Vec3 reflect(const Vec3& wo, const Vec3& h) { return h * (2 * dot(wo, h)) - wo; }

}  // namespace

DielectricBsdf::DielectricBsdf(const Transmission& t, float roughness, bool entering)
    : tint_(t.color),
      f0_(normalReflectance(t.ior)),
      eta_(t.thin     ? 1
           : entering ? Real(t.ior)
                      : 1 / Real(t.ior)),
      alpha_(Real(roughness) * Real(roughness)),
      thin_(t.thin),
      // below the alpha the metallic-roughness BRDF takes as a mirror the surface is smooth; index
      // 1 bends nothing: the surface lets the light straight through, as pbrt does
      smooth_(alpha_ < kMinAlpha || (!t.thin && t.ior == 1)) {}

// Schlick's cosine is the one on the side of the lower index (render/refraction.cpp): the
// incident side when the light goes into the denser medium, the transmitted side otherwise.
Real DielectricBsdf::fresnel(Real c) const {
    if (eta_ >= 1) return schlickFresnel(float(c), f0_);
    const Real sin2Out = (1 - c * c) / (eta_ * eta_);
    if (sin2Out >= 1) return 1;  // total internal reflection
    return schlickFresnel(float(std::sqrt(1 - sin2Out)), f0_);
}

// Walter et al. 2007, eq. 16: reflection's half vector is wo + wi; refraction's, wo + eta wi.
// A thin sheet's transmitted direction is a reflected one mirrored through the surface.
std::optional<Vec3> DielectricBsdf::halfVector(const Vec3& wo, const Vec3& wi) const {
    const bool reflected = wi.z > 0;
    Vec3 h = reflected ? wo + wi : thin_ ? wo + flipZ(wi) : wo + wi * eta_;
    const Real lengthSq = dot(h, h);
    if (!(lengthSq > 0)) return std::nullopt;
    h = h / std::sqrt(lengthSq);
    if (h.z < 0) h = -h;
    // facets seen from their back by either direction reflect and transmit nothing
    const Vec3 side = thin_ && !reflected ? flipZ(wi) : wi;
    if (dot(h, wo) <= 0 || dot(h, side) * side.z <= 0) return std::nullopt;
    return h;
}

Real DielectricBsdf::visibleNormalPdf(const Vec3& wo, const Vec3& h) const {
    return smithG1(wo, alpha_) * std::max(Real(0), dot(wo, h)) * ggxD(h, alpha_) / wo.z;
}

Color DielectricBsdf::evaluate(const Vec3& wo, const Vec3& wi) const {
    if (smooth_ || wo.z <= 0 || wi.z == 0) return {};
    const std::optional<Vec3> h = halfVector(wo, wi);
    if (!h) return {};
    const Real cosO = dot(wo, *h);
    const Real F = fresnel(cosO);
    const Real dg = ggxD(*h, alpha_) / (1 + smithLambda(wo, alpha_) + smithLambda(wi, alpha_));
    if (wi.z > 0) return Color{1, 1, 1} * float(dg * F / (4 * wo.z));
    if (thin_) return tint_ * float(dg * (1 - F) / (4 * wo.z));
    // Walter et al. 2007, eq. 21, with the radiance scaled by 1 / eta^2 across the boundary
    const Real cosI = dot(wi, *h);
    const Real denom = (cosI + cosO / eta_) * (cosI + cosO / eta_);
    return tint_ * float(dg * (1 - F) * std::abs(cosI * cosO) / (wo.z * denom * eta_ * eta_));
}

Real DielectricBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    if (smooth_ || wo.z <= 0 || wi.z == 0) return 0;
    const std::optional<Vec3> h = halfVector(wo, wi);
    if (!h) return 0;
    const Real cosO = dot(wo, *h);
    const Real F = fresnel(cosO);
    const Real facets = visibleNormalPdf(wo, *h);
    if (wi.z > 0) return facets / (4 * cosO) * F;
    if (thin_) return facets / (4 * cosO) * (1 - F);
    const Real cosI = dot(wi, *h);
    const Real denom = (cosI + cosO / eta_) * (cosI + cosO / eta_);
    return facets * std::abs(cosI) / denom * (1 - F);  // d(h)/d(wi), Walter et al. eq. 17
}

std::optional<BsdfSample> DielectricBsdf::sampleSmooth(const Vec3& wo, Real u1) const {
    const Real F = fresnel(wo.z);
    if (u1 < F) return BsdfSample{{-wo.x, -wo.y, wo.z}, {1, 1, 1}, F, true};
    if (thin_) return BsdfSample{-wo, tint_, 1 - F, true};
    const std::optional<Vec3> wi = refractDirection(-wo, {0, 0, 1}, 1 / eta_);
    if (!wi) return std::nullopt;
    return BsdfSample{*wi, tint_ * float(1 / (eta_ * eta_)), 1 - F, true};
}

std::optional<BsdfSample> DielectricBsdf::sample(const Vec3& wo, Real u1, Real u2, Real u3) const {
    if (wo.z <= 0) return std::nullopt;
    if (smooth_) return sampleSmooth(wo, u1);
    const Vec3 h = sampleVisibleNormal(wo, alpha_, u2, u3);
    Vec3 wi;
    if (u1 < fresnel(dot(wo, h))) {
        wi = reflect(wo, h);
        if (wi.z <= 0) return std::nullopt;
    } else if (thin_) {
        wi = flipZ(reflect(wo, h));
        if (wi.z >= 0) return std::nullopt;
    } else {
        const std::optional<Vec3> refracted = refractDirection(-wo, h, 1 / eta_);
        if (!refracted || refracted->z >= 0) return std::nullopt;
        wi = *refracted;
    }
    const Real density = pdf(wo, wi);
    if (!(density > 0)) return std::nullopt;
    return BsdfSample{wi, evaluate(wo, wi) * float(1 / density), density};
}

}  // namespace rt
