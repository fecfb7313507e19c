// Exact overlap tests of a primitive with an axis-aligned box, used to sort primitives
// into the children of a BSP node (thesis 2.4.1): a primitive whose bounding box touches
// a voxel may still miss it, and every such false reference costs intersection tests.
// Both tests treat the box as closed: touching counts as overlapping.
#pragma once

#include "core/aabb.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace rt {

// Separating-axis test of Akenine-Moller 2001 (thesis [10]): the three box normals,
// the triangle's normal and the nine cross products of edges and box axes.
bool overlaps(const Triangle& tri, const Aabb& box);

// Arvo 1990 (thesis [9]) for a hollow sphere: the surface meets the box when the
// nearest point of the box is inside the sphere and the farthest is not. Only the
// surface can be hit by a ray, so a voxel wholly inside a sphere does not reference it.
bool overlaps(const Sphere& sphere, const Aabb& box);

}  // namespace rt
