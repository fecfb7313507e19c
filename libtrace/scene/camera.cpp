#include "scene/camera.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rt {

namespace {

// --frame leaves this much room around the bounding sphere (10 % of its radius), as modelling
// tools do, so that the silhouette never touches the picture's edge.
constexpr Real kFrameMargin = Real(1.1);

Real radians(Real degrees) { return degrees * kPi / 180; }

Vec3 viewDirection(const Camera& c) {
    const Vec3 view = c.destination - c.origin;
    if (!(length(view) > 0)) throw InputError("camera: origin and destination are the same point");
    return normalize(view);
}

// The same angle of view stated as an fov, so that moving the eye keeps it: a camera with
// neither fov nor f takes its focal distance from the eye's distance to the destination.
void fixAngleOfView(Camera& c) {
    if (c.fovDegrees && c.zoom == 100) return;
    c.fovDegrees = c.horizontalFovDegrees();
    c.focalDistance.reset();
    c.zoom = 100;
}

}  // namespace

Real Camera::focalPixels(int imageWidth) const {
    const Real width = Real(imageWidth);
    Real f;
    if (fovDegrees)
        f = std::abs(width / (2 * std::tan(*fovDegrees * kPi / 360)));
    else  // pixels at the reference width; at that width the factor is exactly 1
        f = focalDistance.value_or(length(origin - destination)) * (width / Real(kReferenceWidth));
    return f * zoom / 100;
}

Real Camera::horizontalFovDegrees() const {
    return 2 * std::atan(Real(kReferenceWidth) / 2 / focalPixels(kReferenceWidth)) * 180 / kPi;
}

void applyOverrides(Camera& camera, const CameraOverrides& o, const Aabb& bounds, Real aspect) {
    if (o.lookFrom || o.lookAt) fixAngleOfView(camera);  // a moved camera keeps its lens
    if (o.lookFrom) camera.origin = *o.lookFrom;
    if (o.lookAt) camera.destination = *o.lookAt;
    if (o.up) camera.up = *o.up;
    if (o.fovDegrees) {
        if (!(*o.fovDegrees > 0 && *o.fovDegrees < 180))
            throw InputError("--fov must be between 0 and 180 degrees (exclusive)");
        camera.fovDegrees = *o.fovDegrees;
        camera.focalDistance.reset();
        camera.zoom = 100;
    }
    if (o.frame) frameBounds(camera, bounds, aspect);
}

void frameBounds(Camera& camera, const Aabb& bounds, Real aspect) {
    if (bounds.empty()) throw InputError("--frame: the scene has no geometry to frame");
    const Vec3 view = viewDirection(camera);
    fixAngleOfView(camera);
    const Real halfWidth = radians(*camera.fovDegrees) / 2;
    const Real halfHeight = std::atan(std::tan(halfWidth) / aspect);
    const Real radius = std::max(length(bounds.diagonal()) / 2, Real(1e-6)) * kFrameMargin;
    camera.destination = bounds.center();
    camera.origin = camera.destination - view * (radius / std::sin(std::min(halfWidth, halfHeight)));
}

Camera orbited(const Camera& camera, Real degrees) {
    const Vec3 axis = normalize(camera.up);
    const Real c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    const Vec3 v = camera.origin - camera.destination;
    // Rodrigues' rotation of v about the axis. The origin moves by the change of v, which is
    // exactly zero at 0 degrees: frame 0 of a turntable is the plain render, bit for bit.
    const Vec3 turned = v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
    Camera out = camera;
    out.origin = camera.origin + (turned - v);
    return out;
}

}  // namespace rt
