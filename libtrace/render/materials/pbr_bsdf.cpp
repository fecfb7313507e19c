#include "render/materials/pbr_bsdf.h"

#include <algorithm>
#include <cmath>

#include "render/materials/microfacet.h"
#include "render/sobol_sampler.h"

namespace rt {

namespace {

Vec3 sampleCosine(Real u1, Real u2) {
    const Real r = std::sqrt(u1);
    const Real phi = 2 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(Real(0), 1 - u1))};
}

// The directional albedo E(mu, roughness) of the GGX lobe with Fresnel 1, and its cosine-weighted
// average, tabulated once (Kulla and Conty 2017, "Revisiting Physically Based Shading at
// Imageworks"): the energy single scattering loses, 1 - E, is what the multiple-scattering lobe
// gives back. Each entry is a 64-sample visible-normal estimate (weight G2 / G1, little variance)
// on a fixed (0,2)-sequence, so the table is the same on every run.
class GgxAlbedoTable {
public:
    static const GgxAlbedoTable& get() {
        static const GgxAlbedoTable table;
        return table;
    }
    Real albedo(Real mu, Real roughness) const { return lookup(albedo_, mu, roughness); }
    Real average(Real roughness) const {
        const Real r = std::clamp(roughness * kSize - Real(0.5), Real(0), Real(kSize - 1));
        const int j = std::min(int(r), kSize - 2);
        return average_[j] + (average_[j + 1] - average_[j]) * (r - Real(j));
    }

private:
    static constexpr int kSize = 32, kSamples = 64;

    GgxAlbedoTable() {
        for (int j = 0; j < kSize; ++j) {
            const Real roughness = (Real(j) + Real(0.5)) / kSize;
            const Real alpha = std::max(roughness * roughness, kMinAlpha);
            Real weighted = 0;
            for (int i = 0; i < kSize; ++i) {
                const Real mu = (Real(i) + Real(0.5)) / kSize;
                const Vec3 wo{std::sqrt(1 - mu * mu), 0, mu};
                Real sum = 0;
                for (std::uint32_t k = 0; k < kSamples; ++k) {
                    const Real u1 = (Real(k) + Real(0.5)) / kSamples;
                    const Real u2 = Real(sobol_detail::reverseBits(k)) * Real(0x1p-32);
                    const Vec3 h = sampleVisibleNormal(wo, alpha, u1, u2);
                    const Vec3 wi = h * (2 * dot(wo, h)) - wo;
                    if (wi.z > 0)
                        sum += (1 + smithLambda(wo, alpha)) / (1 + smithLambda(wo, alpha) + smithLambda(wi, alpha));
                }
                albedo_[i][j] = sum / kSamples;
                weighted += albedo_[i][j] * mu;
            }
            average_[j] = 2 * weighted / kSize;
        }
    }
    static Real lookup(const Real (&t)[kSize][kSize], Real mu, Real roughness) {
        const Real x = std::clamp(mu * kSize - Real(0.5), Real(0), Real(kSize - 1));
        const Real y = std::clamp(roughness * kSize - Real(0.5), Real(0), Real(kSize - 1));
        const int i = std::min(int(x), kSize - 2), j = std::min(int(y), kSize - 2);
        const Real fx = x - Real(i), fy = y - Real(j);
        const Real low = t[i][j] + (t[i + 1][j] - t[i][j]) * fx;
        const Real high = t[i][j + 1] + (t[i + 1][j + 1] - t[i][j + 1]) * fx;
        return low + (high - low) * fy;
    }

    Real albedo_[kSize][kSize];  // [mu][roughness]
    Real average_[kSize];
};

}  // namespace

PbrBsdf::PbrBsdf(const Color& baseColor, const MetallicRoughness& factors)
    : base_(baseColor), f_(factors), alpha_(std::max(Real(factors.roughness) * Real(factors.roughness), kMinAlpha)) {
    const GgxAlbedoTable& table = GgxAlbedoTable::get();
    averageAlbedo_ = table.average(Real(factors.roughness));
    // Kulla and Conty's Fresnel for light that scatters several times: with F_avg, Schlick's
    // Fresnel averaged over the hemisphere, F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),
    // so that a white metal (F_avg = 1) gives back exactly what single scattering lost.
    const auto tint = [this](float f0) {
        const Real average = f0 + (1 - f0) / 21;
        return float(average * average * averageAlbedo_ / (1 - average * (1 - averageAlbedo_)));
    };
    multipleScatteringFresnel_ = {tint(baseColor.r), tint(baseColor.g), tint(baseColor.b)};
}

// The metal's multiple-scattering lobe: F_ms (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)), a
// diffuse-like lobe whose integral is F_ms (1 - E(mu_o)), the energy the single-scattering lobe
// lost at wo's angle; albedoO is E(mu_o).
Color PbrBsdf::multipleScattering(const Vec3& wi, Real albedoO) const {
    if (f_.metallic <= 0 || !(averageAlbedo_ < 1)) return {};
    const Real lost = (1 - albedoO) * (1 - GgxAlbedoTable::get().albedo(wi.z, f_.roughness));
    return multipleScatteringFresnel_ * float(lost / (kPi * (1 - averageAlbedo_)));
}

Real PbrBsdf::albedoAt(const Vec3& wo) const {
    return f_.metallic > 0 ? GgxAlbedoTable::get().albedo(wo.z, f_.roughness) : 0;
}

PbrBsdf::Pair PbrBsdf::pair(const Vec3& wo, const Vec3& wi, Real albedoO) const {
    const Vec3 h = normalize(wo + wi);
    return {h, ggxD(h, alpha_), smithLambda(wo, alpha_), albedoO};
}

Color PbrBsdf::evaluate(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0 || wi.z <= 0) return {};
    return evaluate(wo, wi, pair(wo, wi, albedoAt(wo)));
}

Color PbrBsdf::evaluate(const Vec3& wo, const Vec3& wi, const Pair& p) const {
    const auto s = float(schlickWeight(dot(wo, p.h)));
    const float dielectricF = f_.specular * (kDielectricF0 + (1 - kDielectricF0) * s);
    const Color metalF = base_ + (Color{1, 1, 1} + base_ * -1.0f) * s;
    const auto dv = float(p.d / ((1 + p.lambdaO + smithLambda(wi, alpha_)) * 4 * wo.z * wi.z));
    const float m = f_.metallic;
    const Color diffuse = base_ * ((1 - m) * (1 - dielectricF) / float(kPi));
    const Color glossy = (Color{1, 1, 1} * ((1 - m) * dielectricF) + metalF * m) * dv;
    return (diffuse + glossy + multipleScattering(wi, p.albedoO) * m) * float(wi.z);
}

// The share of reflected light the glossy lobe carries at wo's angle, by Schlick's Fresnel at
// the normal: the better the lobe choice follows f, the less noise. albedoO: albedoAt(wo).
Real PbrBsdf::glossyProbability(const Vec3& wo, Real albedoO) const {
    const Real s = schlickWeight(wo.z);
    const Real dielectricF = f_.specular * (kDielectricF0 + (1 - kDielectricF0) * s);
    const Real metalF = luminance(base_) + (1 - luminance(base_)) * s;
    const Real m = f_.metallic;
    const Real glossy = (1 - m) * dielectricF + m * metalF * albedoO;
    // the cosine-sampled share: the base, and the metal's multiple scattering
    const Real diffuse =
        (1 - m) * (1 - dielectricF) * luminance(base_) + m * luminance(multipleScatteringFresnel_) * (1 - albedoO);
    return glossy + diffuse > 0 ? glossy / (glossy + diffuse) : Real(0.5);
}

Real PbrBsdf::pdf(const Vec3& wo, const Vec3& wi) const {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    const Real albedoO = albedoAt(wo);
    return pdf(wo, wi, glossyProbability(wo, albedoO), pair(wo, wi, albedoO));
}

Real PbrBsdf::pdf(const Vec3& wo, const Vec3& wi, Real glossyShare, const Pair& p) const {
    // visible normals: D_wo(h) = G1(wo) (wo.h) D(h) / wo.z, and d(wi)/d(h) = 1 / (4 wo.h)
    const Real glossy = 1 / (1 + p.lambdaO) * p.d / (4 * wo.z);
    const Real diffuse = wi.z / kPi;
    return glossyShare * glossy + (1 - glossyShare) * diffuse;
}

std::optional<BsdfSample> PbrBsdf::sample(const Vec3& wo, Real u1, Real u2, Real u3) const {
    if (wo.z <= 0) return std::nullopt;
    const Real albedoO = albedoAt(wo);  // once: it costs a table lookup
    const Real glossyShare = glossyProbability(wo, albedoO);
    Vec3 wi;
    if (u1 < glossyShare) {
        const Vec3 h = sampleVisibleNormal(wo, alpha_, u2, u3);
        wi = h * (2 * dot(wo, h)) - wo;
    } else {
        wi = sampleCosine(u2, u3);
    }
    if (wi.z <= 0) return std::nullopt;
    const Pair p = pair(wo, wi, albedoO);
    const Real density = pdf(wo, wi, glossyShare, p);
    if (!(density > 0)) return std::nullopt;
    return BsdfSample{wi, evaluate(wo, wi, p) * float(1 / density), density};
}

}  // namespace rt
