// Per-corner shading data of triangles: vertex normals, texture coordinates and vertex
// colours. It is kept apart from the triangles, which traversal reads in its hot loop
// (Primitives' flat arrays stay 9 coordinates a triangle), and only what exists is stored:
// each attribute is an array indexed by triangle index that ends after the last triangle
// that has the attribute. A triangle past its end takes the neutral value: no normals
// (shade with the geometric normal), texture coordinates (0, 0), white (no tint).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/vec3.h"

namespace rt {

// Three values of N floats, one per corner p0, p1, p2, stored in float as RAW models keep them.
template <int N>
struct CornerValues {
    std::array<float, 3 * N> values{};

    // The value at barycentric (u, v): weight 1 - u - v for p0, u for p1, v for p2 (as Hit gives them).
    std::array<Real, N> at(Real u, Real v) const {
        const Real w = 1 - u - v;
        std::array<Real, N> out;
        for (int i = 0; i < N; ++i) out[i] = w * values[i] + u * values[N + i] + v * values[2 * N + i];
        return out;
    }
    Vec3 corner(int c) const requires(N == 3) { return {values[3 * c], values[3 * c + 1], values[3 * c + 2]}; }
};

using CornerNormals = CornerValues<3>;  // unit, or all zero: the geometric normal
using CornerUvs = CornerValues<2>;
// Tangent-space frames for normal maps (geometry/tangents.h): unit tangent xyz along +u and
// the handedness w (+1 or -1) of the bitangent w * cross(normal, tangent), which points up the
// image (-v: rt's v runs down it, as glTF's).
using CornerTangents = CornerValues<4>;
struct CornerColors : CornerValues<3> {
    CornerColors() { values.fill(1); }
};

// One attribute for all triangles, indexed by triangle index; shorter than the triangle
// count when the last triangles do not have it (they read the neutral value).
template <class T>
class CornerAttribute {
public:
    bool empty() const { return values_.empty(); }
    std::size_t size() const { return values_.size(); }
    // The value of triangle i, or nullptr when it has the neutral one.
    const T* find(std::size_t i) const { return i < values_.size() ? &values_[i] : nullptr; }
    // Gives triangle i its value; triangles before it that had none keep the neutral one.
    void set(std::size_t i, const T& value) {
        if (values_.size() <= i) values_.resize(i + 1);
        values_[i] = value;
    }
    // Appends `other`'s values for triangles numbered from `offset` on.
    void append(const CornerAttribute& other, std::size_t offset) {
        if (other.empty()) return;
        values_.resize(offset);
        values_.insert(values_.end(), other.values_.begin(), other.values_.end());
    }
    std::size_t memoryBytes() const { return values_.capacity() * sizeof(T); }

private:
    std::vector<T> values_;
};

struct TriangleShading {
    CornerAttribute<CornerNormals> normals;
    CornerAttribute<CornerUvs> uvs;
    CornerAttribute<CornerColors> colors;
    CornerAttribute<CornerTangents> tangents;

    bool empty() const { return normals.empty() && uvs.empty() && colors.empty() && tangents.empty(); }
    // Appends `other` for triangles numbered from `offset` (this side's triangle count) on.
    void append(const TriangleShading& other, std::size_t offset) {
        normals.append(other.normals, offset);
        uvs.append(other.uvs, offset);
        colors.append(other.colors, offset);
        tangents.append(other.tangents, offset);
    }
    std::size_t memoryBytes() const {
        return normals.memoryBytes() + uvs.memoryBytes() + colors.memoryBytes() + tangents.memoryBytes();
    }
};

}  // namespace rt
