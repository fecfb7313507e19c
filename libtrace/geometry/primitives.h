// The scene's geometry in world space, flat and compact: one array per primitive kind
// and a parallel array of material indices, no heap object per primitive (as Embree
// keeps its geometry). Primitive ids run over triangles first, then spheres:
// id < triangleCount() is a triangle, the rest are spheres.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/sphere.h"
#include "geometry/triangle.h"

namespace rt {

class Primitives {
public:
    void addTriangle(const Triangle& t, std::uint32_t material);
    void addSphere(const Sphere& s, std::uint32_t material);
    void append(const Primitives& other);
    void reserveTriangles(std::size_t n);

    std::uint32_t size() const { return std::uint32_t(triangles_.size() + spheres_.size()); }
    std::uint32_t triangleCount() const { return std::uint32_t(triangles_.size()); }
    std::uint32_t sphereCount() const { return std::uint32_t(spheres_.size()); }
    bool isSphere(std::uint32_t id) const { return id >= triangles_.size(); }

    const std::vector<Triangle>& triangles() const { return triangles_; }
    const std::vector<Sphere>& spheres() const { return spheres_; }
    const Triangle& triangle(std::uint32_t id) const { return triangles_[id]; }
    const Sphere& sphere(std::uint32_t id) const { return spheres_[id - triangles_.size()]; }
    std::uint32_t material(std::uint32_t id) const {
        return isSphere(id) ? sphereMaterials_[id - triangles_.size()] : triangleMaterials_[id];
    }

    Aabb bounds(std::uint32_t id) const { return isSphere(id) ? sphere(id).bounds() : triangle(id).bounds(); }
    Aabb bounds() const;  // of everything

    // Nearest hit of primitive `id` closer than tMax; updates `hit` and returns true if found.
    bool intersect(std::uint32_t id, const Ray& ray, Real tMax, Hit& hit) const {
        if (isSphere(id)) {
            if (!intersectSphere(sphere(id), ray, tMax, hit.t)) return false;
            hit.u = hit.v = 0;
        } else if (!intersectTriangle(triangle(id), ray, tMax, hit.t, hit.u, hit.v)) {
            return false;
        }
        hit.prim = id;
        return true;
    }

    // Unit geometric normal at a point on primitive `id`.
    Vec3 normal(std::uint32_t id, const Vec3& point) const {
        return isSphere(id) ? sphere(id).normal(point) : triangle(id).normal();
    }

    // Bytes held per primitive (geometry plus material index), for the statistics.
    std::size_t memoryBytes() const;

private:
    std::vector<Triangle> triangles_;
    std::vector<std::uint32_t> triangleMaterials_;
    std::vector<Sphere> spheres_;
    std::vector<std::uint32_t> sphereMaterials_;
};

}  // namespace rt
