// Primary rays of the two-point camera of thesis 2.1.1. The thesis builds
// P(x,y) = O + p + (x - w/2) u + (y - h/2) v with p along the viewing axis and f in pixels;
// here u points to the image's right in a right-handed world (u = forward x up), so
// the image is not mirrored, and row 0 is the top of the image.
#pragma once

#include "core/ray.h"
#include "render/ray_differential.h"
#include "scene/scene.h"

namespace rt {

class CameraRays {
public:
    // Throws rt::InputError if origin and destination coincide or up is parallel to the view.
    CameraRays(const Camera& camera, int width, int height);

    // The ray through image position (x, y) in pixels; (x + 0.5, y + 0.5) is the centre of pixel (x, y).
    Ray at(Real x, Real y) const {
        const Vec3 d = forward_ + right_ * (x - halfWidth_) - up_ * (y - halfHeight_);
        return {origin_, normalize(d)};
    }

    // The differential of `ray`, the ray at(x, y): how the directions of the rays one pixel to
    // the right and one down differ from it, times `scale` (render/ray_differential.h).
    RayDifferential differentialAt(Real x, Real y, const Ray& ray, Real scale) const {
        return {
            {}, (at(x + 1, y).direction - ray.direction) * scale, {}, (at(x, y + 1).direction - ray.direction) * scale};
    }
    // The angle one pixel subtends at the image's centre, in radians: how fast a ray cone widens.
    Real pixelAngle() const { return 1 / length(forward_); }

    int width() const { return width_; }
    int height() const { return height_; }

private:
    Vec3 origin_;
    Vec3 forward_;  // f times the unit viewing direction
    Vec3 right_;    // one pixel to the right
    Vec3 up_;       // one pixel up
    Real halfWidth_, halfHeight_;
    int width_, height_;
};

}  // namespace rt
