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
// and optionally a block (geometry/leaf_block.h: LeafBlockOf<K>, specialized in the header this
// file includes for K), which the trees' leaves then test kSimdWidth at a time.
#pragma once

#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "geometry/clip.h"
#include "geometry/disk.h"
#include "geometry/frustum.h"
#include "geometry/overlap.h"
#include "geometry/sphere.h"
#include "geometry/sphere_block.h"
#include "geometry/triangle.h"
#include "geometry/triangle_block.h"

namespace rt {

// Primitive ids run over the kinds in this order: all triangles, then all spheres, ...
using PrimitiveKinds = std::tuple<Triangle, Sphere, Cylinder, Cone, Disk>;

inline constexpr std::size_t kKindCount = std::tuple_size_v<PrimitiveKinds>;

// Calls f(std::type_identity<K>{}) for each kind K, in list order.
template <class F>
constexpr void forEachKind(F&& f) {
    [&]<std::size_t... I>(std::index_sequence<I...>) {
        (f(std::type_identity<std::tuple_element_t<I, PrimitiveKinds>>{}), ...);
    }
    (std::make_index_sequence<kKindCount>{});
}

// The kinds with a block (geometry/leaf_block.h), in list order: the trees' leaves hold them in
// blocks, and test the others one at a time.
template <class Kinds>
struct BlockKindsOf;
template <class... K>
struct BlockKindsOf<std::tuple<K...>> {
    using type = decltype(std::tuple_cat(std::conditional_t<BlockTested<K>, std::tuple<K>, std::tuple<>>{}...));
};
using BlockKinds = typename BlockKindsOf<PrimitiveKinds>::type;
inline constexpr std::size_t kBlockKindCount = std::tuple_size_v<BlockKinds>;

}  // namespace rt
