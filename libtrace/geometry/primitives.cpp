#include "geometry/primitives.h"

namespace rt {

void Primitives::addTriangle(const Triangle& t, std::uint32_t material) {
    triangles_.push_back(t);
    triangleMaterials_.push_back(material);
}

void Primitives::addSphere(const Sphere& s, std::uint32_t material) {
    spheres_.push_back(s);
    sphereMaterials_.push_back(material);
}

void Primitives::append(const Primitives& other) {
    triangles_.insert(triangles_.end(), other.triangles_.begin(), other.triangles_.end());
    triangleMaterials_.insert(triangleMaterials_.end(), other.triangleMaterials_.begin(),
                              other.triangleMaterials_.end());
    spheres_.insert(spheres_.end(), other.spheres_.begin(), other.spheres_.end());
    sphereMaterials_.insert(sphereMaterials_.end(), other.sphereMaterials_.begin(), other.sphereMaterials_.end());
}

void Primitives::reserveTriangles(std::size_t n) {
    triangles_.reserve(n);
    triangleMaterials_.reserve(n);
}

Aabb Primitives::bounds() const {
    Aabb b;
    for (const Triangle& t : triangles_) b.extend(t.bounds());
    for (const Sphere& s : spheres_) b.extend(s.bounds());
    return b;
}

std::size_t Primitives::memoryBytes() const {
    return triangles_.capacity() * sizeof(Triangle) + triangleMaterials_.capacity() * sizeof(std::uint32_t) +
           spheres_.capacity() * sizeof(Sphere) + sphereMaterials_.capacity() * sizeof(std::uint32_t);
}

}  // namespace rt
