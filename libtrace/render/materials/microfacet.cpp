#include "render/materials/microfacet.h"

#include <algorithm>
#include <cmath>

namespace rt {

Real schlickWeight(Real cosine) {
    const Real m = std::clamp(1 - cosine, Real(0), Real(1));
    return (m * m) * (m * m) * m;
}

Real ggxD(const Vec3& h, Real alpha) {
    if (h.z <= 0) return 0;
    const Real a2 = alpha * alpha;
    const Real d = h.z * h.z * (a2 - 1) + 1;
    return a2 / (kPi * d * d);
}

Real smithLambda(const Vec3& w, Real alpha) {
    const Real cos2 = w.z * w.z;
    if (cos2 <= 0) return kInfinity;
    const Real tan2 = std::max(Real(0), 1 - cos2) / cos2;
    return (std::sqrt(1 + alpha * alpha * tan2) - 1) / 2;
}

Real smithG1(const Vec3& w, Real alpha) { return 1 / (1 + smithLambda(w, alpha)); }

// Heitz 2018, section 3: stretch the view direction to the hemisphere configuration, sample
// a point on the projected disc (denser on the visible half), lift it to the hemisphere and
// unstretch the normal.
Vec3 sampleVisibleNormal(const Vec3& wo, Real alpha, Real u1, Real u2) {
    const Vec3 v = normalize(Vec3{alpha * wo.x, alpha * wo.y, wo.z});
    const Real lengthSq = v.x * v.x + v.y * v.y;
    const Vec3 t1 = lengthSq > 0 ? Vec3{-v.y, v.x, 0} / std::sqrt(lengthSq) : Vec3{1, 0, 0};
    const Vec3 t2 = cross(v, t1);
    const Real r = std::sqrt(u1);
    const Real phi = 2 * kPi * u2;
    const Real p1 = r * std::cos(phi);
    const Real s = Real(0.5) * (1 + v.z);
    const Real p2 = (1 - s) * std::sqrt(std::max(Real(0), 1 - p1 * p1)) + s * r * std::sin(phi);
    const Vec3 n = t1 * p1 + t2 * p2 + v * std::sqrt(std::max(Real(0), 1 - p1 * p1 - p2 * p2));
    return normalize(Vec3{alpha * n.x, alpha * n.y, std::max(Real(0), n.z)});
}

}  // namespace rt
