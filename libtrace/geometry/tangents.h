// Tangent frames for tangent-space normal maps, generated the way MikkTSpace (Mikkelsen 2008,
// the glTF and Blender standard) does closely enough to read the same maps: each triangle's
// tangent and bitangent from its texture-coordinate derivatives, accumulated over the corners
// that share a vertex (position, normal and texture coordinates equal, and the same UV
// orientation, so mirrored halves keep their own frames) weighted by the corner's angle,
// made orthogonal to the vertex normal (Gram-Schmidt), with the handedness as a sign.
#pragma once

#include <cstdint>
#include <functional>

#include "geometry/primitives.h"

namespace rt {

// dP/du and dP/dv of a triangle with texture coordinates `uv` (constant over it); `uvArea`, if
// given, receives twice its signed area in texture space (negative: the texture is mirrored).
// False when the texture coordinates are degenerate (a line or a point).
bool uvDerivatives(const Triangle& tri, const CornerUvs& uv, Vec3& dpdu, Vec3& dpdv, Real* uvArea = nullptr);

// Gives every triangle that has texture coordinates and whose material `wanted` names, and
// no tangents from its file (glTF's TANGENT), per-corner tangents (Primitives::triangleShading().tangents), in the
// space of its vertices.
void generateTangents(Primitives& prims, const std::function<bool(std::uint32_t material)>& wanted);

}  // namespace rt
