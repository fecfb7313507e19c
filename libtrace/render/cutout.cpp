#include "render/cutout.h"

#include "render/materials/material.h"

namespace rt {

// Texture coordinates exist on triangles only; other primitives read the material's alpha at
// (0, 0), as shading does.
bool opaqueAt(const ShadingContext& context, const Material& m, const Hit& hit) {
    const Primitives& prims = context.scene.primitives;
    Real u = 0, v = 0;
    if (const std::optional<std::uint32_t> index = prims.indexIn<Triangle>(hit.prim))
        if (const CornerUvs* uvs = prims.triangleShading().uvs.find(*index)) {
            const auto uv = uvs->at(hit.u, hit.v);
            u = uv[0];
            v = uv[1];
        }
    return materialAlpha(context, m, u, v) >= *m.opacity.cutoff;
}

}  // namespace rt
