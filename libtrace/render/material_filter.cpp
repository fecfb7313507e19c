#include "render/material_filter.h"

#include <algorithm>

#include "render/cutout.h"

namespace rt {

namespace {

// Whether `m` hides its back: single-sided, and no glass with an inside.
bool cullsBackFaces(const Material& m) {
    return !m.doubleSided && !(m.transmission.passesLight() && !m.transmission.thin);
}

// Whether a single-sided primitive `hit.prim` shows its back to the source of `ray`. A camera,
// reflection or refracted ray comes from its origin: the back is seen where the ray meets the
// surface from behind its geometric normal. A shadow ray runs from the shaded point to the light,
// which is at its far end: the light sees the back where the ray meets the front. So a surface
// shadows where the light sees its front, as a rasteriser's shadow map with back faces culled
// from the light. Edge-on (cosine 0) both see the front.
bool showsItsBack(const Primitives& primitives, const Ray& ray, const Hit& hit) {
    const Real cosine = dot(primitives.normal(hit.prim, ray.at(hit.t)), ray.direction);
    return ray.shadow ? cosine < 0 : cosine > 0;
}

// The tests a material's hits take.
enum Test : std::uint8_t { kNone = 0, kCutout = 1, kBackFace = 2 };

std::uint8_t testsOf(const Scene& scene, const Material& m, const ImageTextures* images) {
    return std::uint8_t((cutsOut(scene, m, images) ? kCutout : kNone) | (cullsBackFaces(m) ? kBackFace : kNone));
}

}  // namespace

MaterialFilter::MaterialFilter(const Scene& scene, const ImageTextures* images) : scene_(scene), images_(images) {
    for (const Material& m : scene.materials) tests_.push_back(testsOf(scene, m, images));
}

bool MaterialFilter::accepts(const Ray& ray, const Hit& hit) const {
    const std::uint32_t id = scene_.primitives.material(hit.prim);
    const std::uint8_t tests = id < tests_.size() ? tests_[id] : std::uint8_t(kNone);
    if (tests == kNone) return true;
    if ((tests & kBackFace) && showsItsBack(scene_.primitives, ray, hit)) return false;
    return !(tests & kCutout) || opaqueAt(scene_, scene_.materials[id], hit, images_);
}

std::unique_ptr<MaterialFilter> materialFilter(const Scene& scene, const ImageTextures* images) {
    const auto& ms = scene.materials;
    if (std::none_of(ms.begin(), ms.end(), [&](const Material& m) { return testsOf(scene, m, images) != kNone; }))
        return nullptr;
    return std::make_unique<MaterialFilter>(scene, images);
}

}  // namespace rt
