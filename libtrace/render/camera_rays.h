// Primary rays of the two-point camera of thesis 2.1.1. The thesis builds
// P(x,y) = O + p + (x - w/2) u + (y - h/2) v with p along the viewing axis and f in pixels;
// here u points to the image's right in a right-handed world (u = forward x up), so
// the image is not mirrored, and row 0 is the top of the image.
#pragma once

#include "core/ray.h"
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
