// The closed list of primitive kinds: the one place a kind is added (compare pbrt-v4's
// Shape, a tagged pointer over its list of shape types). Everything that must treat each
// kind (Primitives' flat arrays, the trees' builders, statistics, the scene writer, the
// tests) iterates this list or dispatches over it, so none of them names a kind.
//
// A kind K is a small value type that provides:
//   K::kName                      singular name, plural adds 's' ("triangle", "triangles")
//   K::kTestCost                  cost of one ray test, relative to a triangle's (the SAH's C_I)
//   Aabb K::bounds()              tight bounds
//   Real K::area()                surface area
//   Vec3 K::normal(point)         unit outward geometric normal at a point on the surface
//   Vec3 K::surfacePoint(u, v)    a point on the surface for u, v in [0, 1] (test rays start there)
//   bool K::degenerate()          true if it cannot be hit (zero size, not finite); loaders drop it
// and, found by overload resolution:
//   Aabb clippedBounds(K, box)    bounds of the part inside the box: the KD tree's perfect splits
//   bool overlaps(K, box)         exact, or tight and conservative, overlap with a closed box (the BSP tree)
//   bool intersect(K, ray, tMax, Hit&)  nearest hit with 0 < t < tMax: sets t, u, v
//   bool intersectsAny(K, ray, tMax)    any hit with 0 < t < tMax (shadow rays)
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "geometry/clip.h"
#include "geometry/frustum.h"
#include "geometry/overlap.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace rt {

// Primitive ids run over the kinds in this order: all triangles, then all spheres, ...
using PrimitiveKinds = std::tuple<Triangle, Sphere, Cylinder, Cone>;

inline constexpr std::size_t kKindCount = std::tuple_size_v<PrimitiveKinds>;

// Calls f(std::type_identity<K>{}) for each kind K, in list order.
template <class F>
constexpr void forEachKind(F&& f) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (f(std::type_identity<std::tuple_element_t<I, PrimitiveKinds>>{}), ...);
    }
    (std::make_index_sequence<kKindCount>{});
}

}  // namespace rt
