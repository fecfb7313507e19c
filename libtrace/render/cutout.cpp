#include "render/cutout.h"

#include <algorithm>

namespace rt {

CutoutFilter::CutoutFilter(const Scene& scene, const ImageTextures* images) : scene_(scene), images_(images) {
    for (const Material& m : scene.materials) cutout_.push_back(cutsOut(scene, m, images));
}

// Texture coordinates exist on triangles only; other primitives read the material's alpha at
// (0, 0), as shading does.
bool CutoutFilter::accepts(const Ray&, const Hit& hit) const {
    const std::uint32_t id = scene_.primitives.material(hit.prim);
    if (id >= cutout_.size() || !cutout_[id]) return true;
    const Material& m = scene_.materials[id];
    Real u = 0, v = 0;
    if (const std::optional<std::uint32_t> index = scene_.primitives.indexIn<Triangle>(hit.prim))
        if (const CornerUvs* uvs = scene_.primitives.triangleShading().uvs.find(*index)) {
            const auto uv = uvs->at(hit.u, hit.v);
            u = uv[0];
            v = uv[1];
        }
    return materialAlpha(scene_, m, u, v, images_) >= *m.alphaCutoff;
}

std::unique_ptr<CutoutFilter> cutoutFilter(const Scene& scene, const ImageTextures* images) {
    const auto& ms = scene.materials;
    if (std::none_of(ms.begin(), ms.end(), [&](const Material& m) { return cutsOut(scene, m, images); }))
        return nullptr;
    return std::make_unique<CutoutFilter>(scene, images);
}

}  // namespace rt
