#include "render/cutout.h"

namespace rt {

// Texture coordinates exist on triangles only; other primitives read the material's alpha at
// (0, 0), as shading does.
bool opaqueAt(const Scene& scene, const Material& m, const Hit& hit, const ImageTextures* images) {
    Real u = 0, v = 0;
    if (const std::optional<std::uint32_t> index = scene.primitives.indexIn<Triangle>(hit.prim))
        if (const CornerUvs* uvs = scene.primitives.triangleShading().uvs.find(*index)) {
            const auto uv = uvs->at(hit.u, hit.v);
            u = uv[0];
            v = uv[1];
        }
    return materialAlpha(scene, m, u, v, images) >= *m.alphaCutoff;
}

}  // namespace rt
