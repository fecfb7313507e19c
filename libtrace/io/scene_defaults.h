// The thesis camera (thesis 2.1.1: origin, destination, up, horizontal fov) made from the
// viewpoints files describe, and the camera and light an imported scene gets when its file
// has none, so that every converted scene renders.
#pragma once

#include "core/aabb.h"
#include "io/import.h"

namespace rt {

// World bounds of the instanced models: each model's box, transformed corner by corner
// (a little loose under rotation, which framing does not mind).
Aabb sceneBounds(const Scene& scene);

// The sphere around the box, to frame a scene by: centre and half the diagonal (at least
// 1e-6, so that a flat or point-like scene still has a size); the unit sphere at the origin
// for an empty box.
struct BoundingSphere {
    Vec3 centre;
    Real radius;
};
BoundingSphere boundingSphere(const Aabb& bounds);

// rt's fov is horizontal; files usually give the vertical one.
double horizontalFov(double verticalFovRadians, double aspect);

// The camera at `eye` looking along `forward` with the given up vector and horizontal fov.
// The destination lies along the view at the distance of the scene's centre (1 unit when
// that is behind the camera or there is no geometry), which only matters to readers of the XML.
Camera viewCamera(const Vec3& eye, const Vec3& forward, const Vec3& up, double horizontalFovRadians,
                  const Aabb& bounds);

// For files whose light colours have no units (Assimp's): only their ratios are kept; when
// any light exceeds 1 in a channel, all lights are scaled together so that the brightest channel is 1.
void scaleLightsToUnitPeak(std::vector<Light>& lights);

// If the importer chose no camera (report.cameraUsed empty, or --camera auto), a camera with a
// 50 degree horizontal fov looking at the bounds' centre from the front, right and above, far
// enough for the bounding sphere to fit the narrower side of an image of `options.aspect`. If
// the scene has no light, a headlight: a white point light at the camera, wherever the camera is
// at render time (Light::headlight). Each is recorded in the notes.
void addMissingCameraAndLight(ImportResult& result, const ImportOptions& options);

}  // namespace rt
