// Cut-outs (glTF alphaMode MASK, OBJ map_d): the hit filter that makes rays pass through a
// surface where its material's opacity is below its alpha cut-off. It runs inside traversal
// (geometry/hit_filter.h), for nearest-hit and shadow rays alike, so a masked leaf neither
// shows nor casts a shadow, and the shading never sees the skipped hit.
#pragma once

#include <memory>
#include <vector>

#include "geometry/hit_filter.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

class CutoutFilter final : public HitFilter {
public:
    // The scene (flattened) and `images` must outlive the filter.
    CutoutFilter(const Scene& scene, const ImageTextures* images);

    bool accepts(const Ray& ray, const Hit& hit) const override;

private:
    const Scene& scene_;
    const ImageTextures* images_;
    std::vector<bool> cutout_;  // by material index
};

// A filter for the scene's cut-out materials, or none when no material is one (the
// accelerators then run without a filter).
std::unique_ptr<CutoutFilter> cutoutFilter(const Scene& scene, const ImageTextures* images);

}  // namespace rt
