// Small scenes built in code for the renderer's tests (unit, golden image and determinism),
// so that they need neither the XML loader nor files.
#pragma once

#include <cmath>
#include <initializer_list>
#include <memory>
#include <vector>

#include "accel/build.h"
#include "accel/naive.h"
#include "render/render_settings.h"
#include "render/renderer.h"
#include "scene/scene.h"

namespace rt::test {

// Default render settings for a picture of the given size.
inline RenderSettings picture(int width, int height) {
    RenderSettings r;
    r.width = width;
    r.height = height;
    return r;
}

// The root-mean-square difference of two pictures of one size, over pixels and colour channels.
inline double rmsDifference(const Framebuffer& a, const Framebuffer& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.pixels().size(); ++i) {
        const Color d = a.pixels()[i] + b.pixels()[i] * -1;
        sum += double(d.r) * d.r + double(d.g) * d.g + double(d.b) * d.b;
    }
    return std::sqrt(sum / (3.0 * double(a.pixels().size())));
}

inline std::uint32_t addMaterial(Scene& s, Material m) {
    s.materials.push_back(std::move(m));
    return std::uint32_t(s.materials.size() - 1);
}

// A unit sphere at the origin in one material, seen from (0, 0, -10); no lights yet.
inline Scene sphereSeenFromMinusZ(Material m, Real fovDegrees) {
    Scene s;
    s.background = {0.1f, 0.2f, 0.3f};
    s.camera.origin = {0, 0, -10};
    s.camera.destination = {0, 0, 0};
    s.camera.fovDegrees = fovDegrees;
    s.looseObjects.add<Sphere>({{0, 0, 0}, 1}, addMaterial(s, std::move(m)));
    return s;
}

// sphereSeenFromMinusZ under `lights`, flattened: ready to render.
inline Scene litSphereSeenFromMinusZ(Material m, Real fovDegrees, std::initializer_list<Light> lights) {
    Scene s = sphereSeenFromMinusZ(std::move(m), fovDegrees);
    s.lights.assign(lights);
    s.flatten();
    return s;
}

// A picture and the statistics of its render.
struct Rendered {
    Framebuffer image;
    RenderStats stats;
};

// `scene` rendered through the naive list, the reference every tree agrees with.
inline Rendered renderNaive(const Scene& scene, const RenderSettings& settings) {
    const NaiveAccelerator accel(scene.primitives);
    RenderStats stats;
    Framebuffer image = render(scene, accel, settings, stats);
    return {std::move(image), stats};
}

// A quad as two triangles, corners in order around its edge.
inline void addQuad(Scene& s, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, std::uint32_t material) {
    s.looseObjects.add<Triangle>({a, b, c}, material);
    s.looseObjects.add<Triangle>({a, c, d}, material);
}

// A floor, two lights with a size for soft shadows, and four materials (floor, red with a
// highlight, mirror, glossy) for the objects placed on it.
inline Scene floorAndLights() {
    Scene s;
    s.background = {0.2f, 0.3f, 0.5f};
    s.camera.origin = {0, 2.5, -7};
    s.camera.destination = {0, 0.8, 0};
    s.camera.fovDegrees = 55;
    const auto floor = addMaterial(s, {.name = "floor",
                                       .color = {0.8f, 0.8f, 0.75f},
                                       .phong = {.ambient = 0.1f, .diffuse = 0.8f, .reflection = 0.15f}});
    addMaterial(s, {.name = "red",
                    .color = {0.9f, 0.15f, 0.1f},
                    .phong = {.ambient = 0.1f, .diffuse = 0.7f, .specular = 0.5f, .shininess = 40}});
    addMaterial(s,
                {.name = "mirror",
                 .color = {1, 1, 1},
                 .phong = {.ambient = 0.02f, .diffuse = 0.1f, .specular = 0.6f, .shininess = 80, .reflection = 0.85f}});
    addMaterial(s, {.name = "glossy",
                    .color = {0.3f, 0.5f, 0.9f},
                    .phong = {.ambient = 0.1f, .diffuse = 0.5f, .reflection = 0.5f, .spread = 0.15f}});
    addQuad(s, {-6, 0, -6}, {-6, 0, 6}, {6, 0, 6}, {6, 0, -6}, floor);
    s.lights.push_back({{-4, 6, -4}, {0.7f, 0.7f, 0.65f}, 0.8});
    s.lights.push_back({{5, 4, -2}, {0.3f, 0.3f, 0.35f}, 0.4});
    return s;
}

// Three spheres (diffuse with a highlight, mirror, glossy) on the floor: exercises every
// part of the shading.
inline Scene spheresOnFloor() {
    Scene s = floorAndLights();
    s.looseObjects.add<Sphere>({{-1.8, 0.8, 0.5}, 0.8}, 1);  // red
    s.looseObjects.add<Sphere>({{0.2, 1.1, 1.2}, 1.1}, 2);   // mirror
    s.looseObjects.add<Sphere>({{2.0, 0.6, -0.3}, 0.6}, 3);  // glossy
    s.flatten();
    return s;
}

// The spheres' floor and lights with the spheres replaced by cylinders and cones: upright,
// lying and tilted, a cone to a point and a frustum, so sides and caps both face the camera.
inline Scene cylindersAndCones() {
    Scene s = floorAndLights();
    s.looseObjects.add<Cylinder>({{{-2, 0, 0.5}, {-2, 1.6, 0.5}, 0.6, 0.6}}, 1);       // upright, red
    s.looseObjects.add<Cylinder>({{{-1, 0.4, -1.6}, {1.2, 0.4, -1.2}, 0.4, 0.4}}, 2);  // lying, mirror
    s.looseObjects.add<Cone>({{{0.4, 0, 1.4}, {0.6, 2.2, 1.2}, 1.0, 0}}, 2);           // to a point, mirror
    s.looseObjects.add<Cone>({{{2.3, 0.3, -0.2}, {1.6, 1.2, 0.4}, 0.6, 0.3}}, 3);      // tilted frustum, glossy
    s.flatten();
    return s;
}

// The naive list, the BSP tree, the KD tree and the BVH over `prims`, each with `filter` (may be
// null): the four every agreement test compares.
inline std::vector<std::unique_ptr<Accelerator>> everyAccelerator(const Primitives& prims, const HitFilter* filter) {
    std::vector<std::unique_ptr<Accelerator>> accels;
    for (AccelKind kind : {AccelKind::Naive, AccelKind::Bsp, AccelKind::Kd, AccelKind::Bvh}) {
        AccelSettings settings;
        settings.kind = kind;
        accels.push_back(buildAccelerator(prims, settings));
        accels.back()->setHitFilter(filter);
    }
    return accels;
}

}  // namespace rt::test
