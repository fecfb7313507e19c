// Vertex normals for a model whose source gave none, by crease angle (as Blender's "auto
// smooth" and 3ds Max's smoothing by angle): at each corner the faces that meet at that point
// and bend less than the crease angle from the corner's own face are averaged, weighted by
// their angle at the point (Thürmer and Wüthrich 1998), so a cylinder's side is smooth and its
// rim stays sharp. Corners meet where their positions are the same floats.
#pragma once

#include "scene/scene.h"

namespace rt {

// The default crease angle in degrees (Blender's auto smooth default).
inline constexpr double kDefaultCreaseDegrees = 30;

// Fills model.vertexNormals for a model of triangles that has none (no change otherwise).
// A point shared by more than kMaxSmoothedCorners corners keeps its faces' own normals:
// the averaging is quadratic in their number.
void addCreaseNormals(Model& model, double creaseDegrees = kDefaultCreaseDegrees);

inline constexpr std::size_t kMaxSmoothedCorners = 1024;

}  // namespace rt
