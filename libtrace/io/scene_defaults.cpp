#include "io/scene_defaults.h"

#include <algorithm>
#include <cmath>

#include "io/mesh_data.h"

namespace rt {

Aabb sceneBounds(const Scene& scene) {
    std::vector<Aabb> local(scene.models.size());
    for (std::size_t i = 0; i < scene.models.size(); ++i) local[i] = modelBounds(scene.models[i]);
    Aabb world;
    for (const Instance& inst : scene.instances) {
        const Aabb& box = local[inst.model];
        if (box.empty()) continue;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 p((corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                         (corner & 4) ? box.hi.z : box.lo.z);
            world.extend(inst.transform.point(p));
        }
    }
    return world;
}

BoundingSphere boundingSphere(const Aabb& bounds) {
    if (bounds.empty()) return {Vec3(), Real(1)};
    return {bounds.center(), std::max(length(bounds.diagonal()) / 2, Real(1e-6))};
}

double horizontalFov(double verticalFovRadians, double aspect) {
    return 2 * std::atan(std::tan(verticalFovRadians / 2) * aspect);
}

Camera viewCamera(const Vec3& eye, const Vec3& forward, const Vec3& up, double horizontalFovRadians,
                  const Aabb& bounds) {
    const Vec3 w = normalize(forward);
    Real distance = 1;
    if (!bounds.empty()) {
        const Real along = dot(bounds.center() - eye, w);
        if (along > 0) distance = along;
    }
    Camera camera;
    camera.origin = eye;
    camera.destination = eye + w * distance;
    camera.up = normalize(up);
    camera.fovDegrees = Real(horizontalFovRadians * 180 / kPi);
    return camera;
}

void scaleLightsToUnitPeak(std::vector<Light>& lights) {
    float peak = 0;
    for (const Light& l : lights) peak = std::max({peak, l.color.r, l.color.g, l.color.b});
    if (peak > 1)
        for (Light& l : lights) l.color *= 1 / peak;
}

void addMissingCameraAndLight(ImportResult& result, const ImportOptions& options) {
    const double aspect = options.aspect;
    Scene& scene = result.scene;
    ImportReport& report = result.report;
    if (report.cameraUsed.empty()) {
        constexpr double kFov = 50 * kPi / 180;
        const Aabb bounds = sceneBounds(scene);
        const BoundingSphere sphere = boundingSphere(bounds);
        // Half the narrower opening of the view cone; the bounding sphere fits inside it.
        const double vertical = std::atan(std::tan(kFov / 2) / aspect);
        const double half = std::min(kFov / 2, vertical);
        const Vec3 direction = normalize(Vec3(0.5, 0.5, 1));
        const Vec3 eye = sphere.centre + direction * Real(sphere.radius / std::sin(half));
        scene.camera = viewCamera(eye, sphere.centre - eye, Vec3(0, 1, 0), kFov, bounds);
        report.cameraGenerated = true;
        if (!options.cameraFromCommandLine)
            report.notes.push_back(
                std::string(options.camera == kFramingCamera ? "--camera auto" : "no usable camera") +
                ": made one with a 50 degree fov framing the scene's bounds");
    }
    if (scene.lights.empty()) {
        Light headlight;
        headlight.headlight = true;
        scene.lights.push_back(headlight);
        scene.placeHeadlights();
        report.lightGenerated = true;
        report.notes.push_back(scene.hasEmissiveMaterial()
                                   ? "no light: added a headlight, a white point light at the camera "
                                     "(the path tracer lights the model by its emitters instead)"
                                   : "no light: added a headlight, a white point light at the camera");
    }
}

}  // namespace rt
