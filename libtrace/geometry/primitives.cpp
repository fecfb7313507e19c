#include "geometry/primitives.h"

namespace rt {

void Primitives::append(const Primitives& other) {
    triangleShading_.append(other.triangleShading_, count<Triangle>());
    forEachKind([&]<class K>(std::type_identity<K>) {
        KindArray<K>& to = array<K>();
        const KindArray<K>& from = other.array<K>();
        to.items.insert(to.items.end(), from.items.begin(), from.items.end());
        to.materials.insert(to.materials.end(), from.materials.begin(), from.materials.end());
    });
}

std::uint32_t Primitives::size() const {
    std::size_t n = 0;
    forEachArray([&](const auto& a) { n += a.items.size(); });
    return std::uint32_t(n);
}

std::vector<KindCount> Primitives::countsPerKind() const {
    std::vector<KindCount> counts;
    forEachKind([&]<class K>(std::type_identity<K>) { counts.push_back({std::string(K::kName) + "s", count<K>()}); });
    return counts;
}

Aabb Primitives::bounds() const {
    Aabb b;
    forEachArray([&](const auto& a) {
        for (const auto& p : a.items) b.extend(p.bounds());
    });
    return b;
}

std::size_t Primitives::memoryBytes() const {
    std::size_t bytes = triangleShading_.memoryBytes();
    forEachArray([&](const auto& a) {
        bytes += a.items.capacity() * sizeof(a.items[0]) + a.materials.capacity() * sizeof(std::uint32_t);
    });
    return bytes;
}

}  // namespace rt
