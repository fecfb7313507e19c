// Cut-outs (glTF alphaMode MASK, OBJ map_d): a surface is not there where its material's
// opacity is below its alpha cut-off. The test runs inside traversal as part of the scene's
// material filter (render/material_filter.h), for nearest-hit and shadow rays alike, so a
// masked leaf neither shows nor casts a shadow, and the shading never sees the skipped hit.
#pragma once

#include "geometry/primitives.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

// Whether cut-out material `m` is opaque at `hit` (its opacity at least its cut-off).
// Thread-safe.
bool opaqueAt(const ShadingContext& context, const Material& m, const Hit& hit);

}  // namespace rt
