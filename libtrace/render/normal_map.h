// Tangent-space normal maps in glTF's convention (glTF 2.0, 3.9.3 normalTexture): a texel's
// red, green and blue, each mapped from [0, 1] to [-1, 1], are the normal's components along
// the tangent (+u), the bitangent (up the image) and the vertex normal; red and green are
// multiplied by the material's NormalMap::scale. The tangents are generated when the scene is
// flattened (geometry/tangents.h). Only the shading normal moves: the geometric normal still
// decides ray offsets and sides, and a surface seen from behind gets the mirrored result.
#pragma once

#include "render/ray_differential.h"
#include "render/surface.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

// Perturbs s.shadingNormal of `hit` (on the scene's primitives) by the material's normal map; no
// change without one, without tangents (a triangle without texture coordinates, a sphere) or
// without image lookups.
void applyNormalMap(const ShadingContext& context, const Material& m, const Hit& hit, SurfacePoint& s);

// The surface at `hit` as shading sees it: surfaceAt with the texture coordinates' derivatives
// for the ray's differential (none: zero, textures read unfiltered) and the material's normal map applied,
// the shading normal then kept from mirroring the ray into the surface (keepReflectionAbove): both
// integrators shade with it.
SurfacePoint shadedSurfaceAt(const ShadingContext& context, const Ray& ray, const Hit& hit,
                             const RayDifferential& differential = {});

}  // namespace rt
