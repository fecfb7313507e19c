// The two-point camera of thesis 2.1.1 and what rt-render does to it from the command line:
// overriding its parts, framing the scene (Blender's View All), and orbiting it (turntables).
//
// The focal distance is in pixels (thesis 3.4.2). The thesis rendered at 800 x 600, so rt reads
// a focal distance given in pixels (the `f` attribute, or the origin-destination distance when
// neither fov nor f is given) as pixels of an image kReferenceWidth wide, and scales it with the
// width: a picture keeps its framing at any -x. At 800 pixels wide nothing changes, so the
// thesis's scenes render as the thesis shows them.
#pragma once

#include <optional>
#include <string>

#include "core/aabb.h"
#include "core/vec3.h"

namespace rt {

inline constexpr int kReferenceWidth = 800;

// The focal distance in pixels, for an image w pixels wide: from fov (horizontal angle, degrees)
// as f = w / (2 tan(fov/2)); else the given f; else the distance between origin and destination,
// both of these meaning pixels at kReferenceWidth. zoom scales f in percent.
struct Camera {
    std::string name;  // rt extension: cameras may be named (--camera NAME); empty if not
    Vec3 origin{0, 0, 0};
    Vec3 destination{0, 0, 1};
    Vec3 up{0, 1, 0};
    std::optional<Real> fovDegrees;
    std::optional<Real> focalDistance;
    Real zoom = 100;

    Real focalPixels(int imageWidth) const;
    // The horizontal angle the picture spans, in degrees: the same at any image width.
    Real horizontalFovDegrees() const;
};

// rt-render's camera options: each given part replaces the scene camera's.
struct CameraOverrides {
    std::optional<Vec3> lookFrom;    // --look-from: the origin
    std::optional<Vec3> lookAt;      // --look-at: the destination
    std::optional<Vec3> up;          // --up
    std::optional<Real> fovDegrees;  // --fov: horizontal, degrees; replaces f and zoom
    bool frame = false;              // --frame: fit the scene's bounds, after the others
};

// Applies the overrides to `camera` for an image of the given aspect (width / height);
// `bounds` are the scene's, for --frame. Throws rt::InputError for a fov outside (0, 180) or
// --frame on a scene without geometry.
void applyOverrides(Camera& camera, const CameraOverrides& overrides, const Aabb& bounds, Real aspect);

// Moves the camera along its viewing direction, and points it at the centre of the bounding
// sphere of `bounds`, so that the sphere fits inside the narrower opening of the view with a
// margin. The fov is made explicit first, so that the move does not change it.
void frameBounds(Camera& camera, const Aabb& bounds, Real aspect);

// The camera turned by `degrees` about the axis through its destination along its up vector
// (right-handed: counter-clockwise seen from where up points): one turntable frame. 0 degrees gives the same bits.
Camera orbited(const Camera& camera, Real degrees);

}  // namespace rt
