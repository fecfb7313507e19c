#include "render/materials/clearcoat_bsdf.h"

#include <algorithm>

#include "render/materials/microfacet.h"

namespace rt {

namespace {

// The least share of the samples that go to the coat at normal incidence, where F_c is 0.04: its
// highlight is sharp and bright, and light samples cannot find the sky's share of it.
constexpr Real kMinCoatShare = Real(0.25);

Vec3 reflect(const Vec3& wo, const Vec3& h) { return h * (2 * dot(wo, h)) - wo; }

}  // namespace

ClearcoatBsdf::ClearcoatBsdf(const PbrBsdf& base, float weight, float roughness)
    : base_(base),
      weight_(std::clamp(Real(weight), Real(0), Real(1))),
      alpha_(std::max(Real(roughness) * Real(roughness), kMinAlpha)) {}

Real ClearcoatBsdf::coatFresnel(const Vec3& wo) const {
    return weight_ * (kDielectricF0 + (1 - kDielectricF0) * schlickWeight(wo.z));
}

Real ClearcoatBsdf::coatShare(const Vec3& wo) const { return std::max(coatFresnel(wo), weight_ * kMinCoatShare); }

Color ClearcoatBsdf::evaluate(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0 || wi.z <= 0) return {};
    const Real fresnel = coatFresnel(wo);
    const Vec3 h = normalize(wo + wi);
    const Real dv = ggxD(h, alpha_) / ((1 + smithLambda(wo, alpha_) + smithLambda(wi, alpha_)) * 4 * wo.z);
    return Color{1, 1, 1} * float(fresnel * dv) + base_.evaluate(wo, wi) * float(1 - fresnel);
}

// visible normals: D_wo(h) = G1(wo) (wo.h) D(h) / wo.z, and d(wi)/d(h) = 1 / (4 wo.h)
Real ClearcoatBsdf::coatPdf(const Vec3& wo, const Vec3& wi) const {
    return smithG1(wo, alpha_) * ggxD(normalize(wo + wi), alpha_) / (4 * wo.z);
}

Real ClearcoatBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    const Real share = coatShare(wo);
    return share * coatPdf(wo, wi) + (1 - share) * base_.pdf(wo, wi);
}

std::optional<BsdfSample> ClearcoatBsdf::sample(const Vec3& wo, Real u1, Real u2, Real u3) const {
    if (wo.z <= 0) return std::nullopt;
    const Real share = coatShare(wo);
    Vec3 wi;
    if (u1 < share) {
        wi = reflect(wo, sampleVisibleNormal(wo, alpha_, u2, u3));
    } else {
        const std::optional<BsdfSample> fromBase = base_.sample(wo, (u1 - share) / (1 - share), u2, u3);
        if (!fromBase) return std::nullopt;
        wi = fromBase->wi;
    }
    if (wi.z <= 0) return std::nullopt;
    const Real density = pdf(wo, wi);
    if (!(density > 0)) return std::nullopt;
    return BsdfSample{wi, evaluate(wo, wi) * float(1 / density), density};
}

}  // namespace rt
