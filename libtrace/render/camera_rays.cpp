#include "render/camera_rays.h"

#include "core/error.h"

namespace rt {

CameraRays::CameraRays(const Camera& camera, int width, int height)
    : origin_(camera.origin),
      halfWidth_(Real(width) / 2),
      halfHeight_(Real(height) / 2),
      width_(width),
      height_(height) {
    const Vec3 view = camera.destination - camera.origin;
    if (!(length(view) > 0)) throw InputError("camera: origin and destination are the same point");
    const Vec3 w = normalize(view);
    const Vec3 side = cross(w, camera.up);
    if (!(length(side) > 0)) throw InputError("camera: the up vector is parallel to the viewing direction");
    right_ = normalize(side);
    up_ = cross(right_, w);
    const Real f = camera.focalPixels(width);
    if (!(f > 0) || !std::isfinite(f)) throw InputError("camera: the focal distance must be positive and finite");
    forward_ = w * f;
}

}  // namespace rt
