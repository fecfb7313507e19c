#include "render/material_filter.h"

#include <algorithm>

#include "render/cutout.h"
#include "render/materials/material.h"

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

std::uint8_t testsOf(const ShadingContext& context, const Material& m) {
    return std::uint8_t((cutsOut(context, m) ? kCutout : kNone) | (cullsBackFaces(m) ? kBackFace : kNone));
}

}  // namespace

MaterialFilter::MaterialFilter(const ShadingContext& context) : context_(context) {
    for (const Material& m : context.scene.materials) tests_.push_back(testsOf(context, m));
}

bool MaterialFilter::accepts(const Ray& ray, const Hit& hit) const {
    const Scene& scene = context_.scene;
    const std::uint32_t id = scene.primitives.material(hit.prim);
    const std::uint8_t tests = id < tests_.size() ? tests_[id] : std::uint8_t(kNone);
    if (tests == kNone) return true;
    if ((tests & kBackFace) && showsItsBack(scene.primitives, ray, hit)) return false;
    return !(tests & kCutout) || opaqueAt(context_, scene.materials[id], hit);
}

std::unique_ptr<MaterialFilter> materialFilter(const ShadingContext& context) {
    const auto& ms = context.scene.materials;
    if (std::none_of(ms.begin(), ms.end(), [&](const Material& m) { return testsOf(context, m) != kNone; }))
        return nullptr;
    return std::make_unique<MaterialFilter>(context);
}

}  // namespace rt
