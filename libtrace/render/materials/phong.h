// The Phong illumination model of thesis 2.1.3 for one light:
//   k_d (L.N) i_d + k_s (R.V)^n i_s,
// where R is L mirrored about N. (The thesis prints R = L - 2(L.N)N, which mirrors the
// direction *from* the light; with L pointing to the light, as here, R = 2(L.N)N - L.)
// The diffuse part is tinted by the surface colour, the highlight has the light's colour.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/color.h"
#include "core/vec3.h"
#include "scene/scene.h"

namespace rt {

// surfaceColor: the material's colour where the light falls (tinted by vertex colours);
// n: unit normal facing the viewer; toLight, toViewer: unit vectors from the surface point.
inline Color phongLight(const Material& m, const Color& surfaceColor, const Vec3& n, const Vec3& toLight,
                        const Vec3& toViewer, const Color& lightColor) {
    assert(isUnitLength(n) && isUnitLength(toLight) && isUnitLength(toViewer));  // else (R.V)^n is unbounded
    const Real cosine = dot(n, toLight);
    if (cosine <= 0) return {};
    Color c = lightColor * surfaceColor * (m.phong.diffuse * float(cosine));
    if (m.phong.specular > 0) {
        const Vec3 mirrored = n * (2 * cosine) - toLight;
        const Real rv = dot(mirrored, toViewer);
        if (rv > 0) c += lightColor * (m.phong.specular * float(std::pow(rv, Real(m.phong.shininess))));
    }
    return c;
}

// The ambient term k_a i_a. The thesis takes i_a as the sum of the lights' intensities,
// precomputed once per scene; it is tinted by the surface colour like the diffuse part.
inline Color phongAmbient(const Color& surfaceColor, const Material& m, const Color& ambientLight) {
    return ambientLight * surfaceColor * m.phong.ambient;
}

// The mirror direction of a unit direction d about the unit normal n (thesis 2.1.3, b = a - 2(a.n)n).
// The result is unit only if both are: |b|^2 = |a|^2 + 4 (a.n)^2 (|n|^2 - 1).
inline Vec3 mirror(const Vec3& d, const Vec3& n) {
    assert(isUnitLength(d) && isUnitLength(n));
    return d - n * (2 * dot(d, n));
}

}  // namespace rt
