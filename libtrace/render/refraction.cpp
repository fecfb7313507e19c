#include "render/refraction.h"

#include <algorithm>
#include <cmath>

namespace rt {

std::optional<Vec3> refractDirection(const Vec3& d, const Vec3& n, Real eta) {
    const Real cosIn = std::min(-dot(d, n), Real(1));
    const Real sin2Out = eta * eta * std::max(Real(0), 1 - cosIn * cosIn);
    if (sin2Out >= 1) return std::nullopt;
    const Real cosOut = std::sqrt(1 - sin2Out);
    // The tangential part scales by eta (Snell), the normal part makes the result unit.
    return normalize(d * eta + n * (eta * cosIn - cosOut));
}

float normalReflectance(float ior) {
    const float r = (ior - 1) / (ior + 1);
    return r * r;
}

float schlickFresnel(float cosine, float f0) {
    const float m = 1 - std::clamp(cosine, 0.0f, 1.0f);
    const float m2 = m * m;
    return f0 + (1 - f0) * m2 * m2 * m;
}

RefractionSplit splitAt(const Transmission& t, const Vec3& d, const Vec3& shadingNormal, const Vec3& geometricNormal,
                        bool entering) {
    const float f0 = normalReflectance(t.ior);
    if (t.thin) return {schlickFresnel(float(-dot(d, shadingNormal)), f0), d};
    const Real eta = entering ? 1 / Real(t.ior) : Real(t.ior);
    Vec3 n = shadingNormal;
    std::optional<Vec3> out = refractDirection(d, n, eta);
    if (out && dot(*out, geometricNormal) >= 0) out = refractDirection(d, n = geometricNormal, eta);
    if (!out) return {};  // total internal reflection
    // Schlick's cosine is the one on the side of the lower index: the incident side when
    // going into a denser medium (eta < 1), the transmitted side when coming out of one.
    const Real cosine = eta <= 1 ? -dot(d, n) : -dot(*out, n);
    return {schlickFresnel(float(cosine), f0), *out};
}

Color absorbed(const Transmission& t, Real distance) {
    const float x = float(distance) / t.attenuationDistance;
    const Color& c = t.attenuationColor;
    return {std::pow(c.r, x), std::pow(c.g, x), std::pow(c.b, x)};
}

Color shadowFilter(const Transmission& t, Real cosine) {
    return t.color * (t.weight * (1 - schlickFresnel(float(cosine), normalReflectance(t.ior))));
}

}  // namespace rt
