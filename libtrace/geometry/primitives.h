// The scene's geometry in world space, flat and compact: one array per primitive kind
// (geometry/primitive_kinds.h) and a parallel array of material indices, no heap object
// per primitive (as Embree keeps its geometry). Primitive ids run over the kinds in list
// order, so an id maps to (kind, index) by comparing it with the arrays' sizes: no table.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/primitive_kinds.h"
#include "geometry/triangle_shading.h"

namespace rt {

// How many primitives of one kind a scene holds, for statistics.
struct KindCount {
    std::string name;  // plural: "triangles"
    std::uint32_t count = 0;
};

// Where each kind's primitives and materials are: pointers and counts only, no ownership.
// The hot loops (traversal leaves, the naive list) take a copy as a local before they
// start. A local whose address never leaves the function stays in registers across the
// out-of-line intersection tests of the rarer kinds, which could otherwise (as far as the
// compiler can tell) change the vectors, so it would reload them for every test.
class PrimitiveView {
    template <class K>
    struct KindSpan {
        const K* items = nullptr;
        const std::uint32_t* materials = nullptr;
        std::uint32_t count = 0;
    };
    template <class Kinds>
    struct SpansOf;
    template <class... K>
    struct SpansOf<std::tuple<K...>> {
        using type = std::tuple<KindSpan<K>...>;
    };
    friend class Primitives;

    // Finds the kind holding `index` (counted from the I-th kind on) and calls f(span, index in it):
    // one comparison per kind before it, so the first kinds in the list are found first.
    template <std::size_t I, class F>
    decltype(auto) visitFrom(std::uint32_t index, F&& f) const {
        const auto& span = std::get<I>(spans_);
        if constexpr (I + 1 < kKindCount) {
            if (index >= span.count) return visitFrom<I + 1>(index - span.count, f);
        }
        return f(span, index);
    }

    typename SpansOf<PrimitiveKinds>::type spans_;

public:
    // Calls f(primitive) with primitive `id` as its own type, and returns what f returns.
    template <class F>
    decltype(auto) visit(std::uint32_t id, F&& f) const {
        return visitFrom<0>(id, [&](const auto& s, std::uint32_t i) -> decltype(auto) { return f(s.items[i]); });
    }
    std::uint32_t material(std::uint32_t id) const {
        return visitFrom<0>(id, [](const auto& s, std::uint32_t i) { return s.materials[i]; });
    }

    // Nearest hit of primitive `id` closer than tMax; updates `hit` and returns true if found.
    bool intersect(std::uint32_t id, const Ray& ray, Real tMax, Hit& hit) const {
        if (!visit(id, [&](const auto& p) { return rt::intersect(p, ray, tMax, hit); })) return false;
        hit.prim = id;
        return true;
    }
    // Whether primitive `id` is hit closer than tMax (shadow rays).
    bool intersectsAny(std::uint32_t id, const Ray& ray, Real tMax) const {
        return visit(id, [&](const auto& p) { return rt::intersectsAny(p, ray, tMax); });
    }
};

class Primitives {
    template <class K>
    struct KindArray {
        std::vector<K> items;
        std::vector<std::uint32_t> materials;
    };
    template <class Kinds>
    struct ArraysOf;
    template <class... K>
    struct ArraysOf<std::tuple<K...>> {
        using type = std::tuple<KindArray<K>...>;
    };

    template <class K>
    KindArray<K>& array() {
        return std::get<KindArray<K>>(arrays_);
    }
    template <class K>
    const KindArray<K>& array() const {
        return std::get<KindArray<K>>(arrays_);
    }

    // Calls f(array) for each kind's array.
    template <class F>
    void forEachArray(F&& f) const {
        std::apply([&](const auto&... a) { (f(a), ...); }, arrays_);
    }

public:
    template <class K>
    void add(const K& primitive, std::uint32_t material) {
        array<K>().items.push_back(primitive);
        array<K>().materials.push_back(material);
    }
    template <class K>
    void reserve(std::size_t n) {
        array<K>().items.reserve(n);
        array<K>().materials.reserve(n);
    }
    void append(const Primitives& other);

    std::uint32_t size() const;
    template <class K>
    std::uint32_t count() const {
        return std::uint32_t(array<K>().items.size());
    }
    template <class K>
    const std::vector<K>& all() const {
        return array<K>().items;
    }
    std::vector<KindCount> countsPerKind() const;

    // The arrays as they are now; valid until a primitive is added.
    PrimitiveView view() const {
        PrimitiveView v;
        forEachKind([&]<class K>(std::type_identity<K>) {
            const KindArray<K>& a = array<K>();
            std::get<PrimitiveView::KindSpan<K>>(v.spans_) = {a.items.data(), a.materials.data(), count<K>()};
        });
        return v;
    }

    // The index of primitive `id` in the array of kind K, if it is of that kind.
    template <class K>
    std::optional<std::uint32_t> indexIn(std::uint32_t id) const {
        std::optional<std::uint32_t> index;
        view().visitFrom<0>(id, [&](const auto& span, std::uint32_t i) {
            if constexpr (std::is_same_v<std::remove_cvref_t<decltype(span)>, PrimitiveView::KindSpan<K>>) index = i;
        });
        return index;
    }

    // Vertex normals, texture coordinates and colours by triangle index, for shading only
    // (geometry/triangle_shading.h); empty for scenes without them.
    TriangleShading& triangleShading() { return triangleShading_; }
    const TriangleShading& triangleShading() const { return triangleShading_; }

    // Calls f(primitive) with primitive `id` as its own type, and returns what f returns.
    template <class F>
    decltype(auto) visit(std::uint32_t id, F&& f) const {
        return view().visit(id, std::forward<F>(f));
    }
    std::uint32_t material(std::uint32_t id) const { return view().material(id); }
    Aabb bounds(std::uint32_t id) const {
        return visit(id, [](const auto& p) { return p.bounds(); });
    }
    Aabb bounds() const;  // of everything

    // Unit geometric normal at a point on primitive `id`.
    Vec3 normal(std::uint32_t id, const Vec3& point) const {
        return visit(id, [&](const auto& p) { return p.normal(point); });
    }

    // Bytes held per primitive (geometry plus material index), for the statistics.
    std::size_t memoryBytes() const;

private:
    typename ArraysOf<PrimitiveKinds>::type arrays_;
    TriangleShading triangleShading_;
};

}  // namespace rt
