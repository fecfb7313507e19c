// The hit filter of a scene's materials (geometry/hit_filter.h): the hits that are not there,
// in both integrators.
// - Cut-outs (render/cutout.h): where the opacity is below the alpha cut-off, for every ray.
// - Single-sided materials (glTF's doubleSided false): their back, as the ray's source sees it.
//   A camera, reflection or refracted ray that reaches a single-sided surface from behind passes
//   through it, as glTF viewers cull back faces; a mirror shows what the camera would see from
//   there. A shadow ray (Ray::shadow) is judged from the light's end: the surface blocks it
//   where the light sees its front (the ray meets it from behind) and lets it pass where the
//   light sees its back, as a shadow map drawn with back faces culled from the light
//   (docs/scene-format.md gives the reasons). Glass with an inside (not thin) is two-sided
//   whatever the flag: its back is where rays leave it, and KHR_materials_volume says
//   doubleSided has no effect on volume boundaries.
// Scenes where no material needs a test (the thesis's) get no filter: the accelerators then
// run as before, at no cost.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/hit_filter.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

class MaterialFilter final : public HitFilter {
public:
    // The context's scene (flattened) and image lookups must outlive the filter.
    explicit MaterialFilter(const ShadingContext& context);

    bool accepts(const Ray& ray, const Hit& hit) const override;

private:
    ShadingContext context_;
    std::vector<std::uint8_t> tests_;  // by material index: the tests its hits take (bits)
};

// The filter of the scene's materials, or none when no material is a cut-out or single-sided.
std::unique_ptr<MaterialFilter> materialFilter(const ShadingContext& context);

}  // namespace rt
