// Polygon faces (OBJ's n-gons) as triangles. Every polygon of n corners gives n - 2
// triangles, as Assimp's aiProcess_Triangulate does, so that counts agree with Assimp's.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace rt {

// Appends, as triples of corner numbers (0 .. n-1), n - 2 triangles covering the polygon
// `corners` (n >= 3). Convex polygons become a fan from corner 0; a concave one is ear-clipped
// in the plane it is most nearly parallel to, so the triangles stay inside it. Ear clipping
// costs O(n^3) at worst, so concave polygons above kMaxEarClippedCorners corners, and
// polygons that are not simple (no ear left), fall back to a fan; the return value is false then.
bool triangulatePolygon(std::span<const std::array<float, 3>> corners, std::vector<std::uint32_t>& triangles);

inline constexpr std::size_t kMaxEarClippedCorners = 64;

}  // namespace rt
