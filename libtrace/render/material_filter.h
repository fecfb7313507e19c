// The hit filter of a scene's materials (geometry/hit_filter.h): the hits that are not there
// for any ray, camera, reflection, refraction and shadow rays alike, in both integrators.
// - Cut-outs (render/cutout.h): where the opacity is below the alpha cut-off.
// - Single-sided materials (glTF's doubleSided false): their back. A ray that reaches a
//   single-sided surface from behind passes through it, as glTF viewers cull back faces; a
//   mirror shows what the camera would see from there, and light passes through from behind
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
    // The scene (flattened) and `images` must outlive the filter.
    MaterialFilter(const Scene& scene, const ImageTextures* images);

    bool accepts(const Ray& ray, const Hit& hit) const override;

private:
    const Scene& scene_;
    const ImageTextures* images_;
    std::vector<std::uint8_t> tests_;  // by material index: the tests its hits take (bits)
};

// The filter of the scene's materials, or none when no material is a cut-out or single-sided.
std::unique_ptr<MaterialFilter> materialFilter(const Scene& scene, const ImageTextures* images);

}  // namespace rt
