// The transmitted ray of Whitted's model (Whitted 1980; thesis 2.1, step 5, left it out):
// Snell's law for its direction, total internal reflection, and Schlick's approximation of
// the Fresnel term, which splits the light between the reflected and the transmitted ray.
//
// Which side a ray is on is decided by the geometric normal (a triangle's winding, a
// sphere's outside): a ray that hits the side the normal faces enters the material, one that
// hits the other side leaves it into the air (index 1). Glass should therefore be closed and
// wound outwards; nested media are not tracked. Directions follow the shading normal; if it
// would send the transmitted ray back to the incoming side, the geometric normal decides.
#pragma once

#include <optional>

#include "core/color.h"
#include "core/vec3.h"
#include "scene/transmission.h"

namespace rt {

// Snell's law, n1 sin(theta1) = n2 sin(theta2): the transmitted direction of the unit
// direction d at a surface of unit normal n facing d's side (dot(d, n) <= 0), for
// eta = n1 / n2; none beyond the critical angle (total internal reflection).
std::optional<Vec3> refractDirection(const Vec3& d, const Vec3& n, Real eta);

// The reflectance at normal incidence between two media whose indices have ratio `ior`:
// F0 = ((ior - 1) / (ior + 1))^2, 0.04 for glass (1.5).
float normalReflectance(float ior);

// Schlick's approximation of the Fresnel reflectance: F0 + (1 - F0) (1 - cos)^5, where cos
// is the cosine of the angle on the side of the lower index.
float schlickFresnel(float cosine, float f0);

// How a ray of unit direction d splits at a transmissive surface: the reflected share
// (1 under total internal reflection, and then no direction), and the transmitted direction.
// The normals are unit and face d's origin side; `entering`: d hits the outside.
struct RefractionSplit {
    float reflected = 1;
    Vec3 direction;  // meaningful when reflected < 1
};
RefractionSplit splitAt(const Transmission& t, const Vec3& d, const Vec3& shadingNormal, const Vec3& geometricNormal,
                        bool entering);

// Beer-Lambert: what is left of white light after `distance` inside, attenuationColor^(distance / attenuationDistance).
Color absorbed(const Transmission& t, Real distance);

// What a shadow ray keeps when it crosses the surface straight on at `cosine` (the absolute
// cosine to the normal): weight * colour * (1 - F). Shadow rays do not bend (Whitted's model
// has no caustics), so the Fresnel term is taken on the outside at the straight ray's angle.
Color shadowFilter(const Transmission& t, Real cosine);

}  // namespace rt
