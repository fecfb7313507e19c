// The bounds of the part of a primitive inside a box: the "perfect splits" of Havran
// (thesis [7]) and Wald and Havran 2006 (thesis [12]). A KD node sees each primitive
// through these clipped bounds, so split candidates lie where the primitive really
// enters and leaves the voxel, not where its (often much larger) bounding box does.
#pragma once

#include "core/aabb.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace rt {

// Clips the triangle to the box (Sutherland-Hodgman against the six planes) and returns
// the bounds of the polygon left, inside `box`; an empty box if the triangle misses it.
Aabb clippedBounds(const Triangle& tri, const Aabb& box);

// The clipped bounds of a primitive in the two halves of `box` that the plane x[axis] = pos
// cuts it into (a KD split's children): for a triangle, one clip to the box and one cut, about
// half the work of two clippedBounds.
struct SplitBounds {
    Aabb below, above;
};
// The two halves themselves.
inline SplitBounds splitBox(const Aabb& box, int axis, Real pos) {
    SplitBounds halves{box, box};
    halves.below.hi[axis] = halves.above.lo[axis] = pos;
    return halves;
}
SplitBounds splitClippedBounds(const Triangle& tri, const Aabb& box, int axis, Real pos);
template <class Primitive>
SplitBounds splitClippedBounds(const Primitive& p, const Aabb& box, int axis, Real pos) {
    const SplitBounds halves = splitBox(box, axis, pos);
    return {clippedBounds(p, halves.below), clippedBounds(p, halves.above)};
}

// Exact bounds of the solid ball inside the box. On each axis the ball reaches as far
// as the disc through it still meets the box's rectangle on the other two axes. Empty if
// the surface misses the box (the box may lie wholly inside, see overlaps(Sphere, Aabb)).
Aabb clippedBounds(const Sphere& sphere, const Aabb& box);

}  // namespace rt
