#include "io/primitive_topology.h"

namespace rt {

std::vector<std::uint32_t> triangleCorners(Topology topology, std::span<const std::uint32_t> v) {
    std::vector<std::uint32_t> out;
    const std::size_t n = v.size();
    if (topology == Topology::Triangles) {
        out.assign(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(n - n % 3));
        return out;
    }
    if (n < 3) return out;
    out.reserve(3 * (n - 2));
    for (std::size_t i = 0; i + 2 < n; ++i) {
        if (topology == Topology::Strip)
            out.insert(out.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
        else
            out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
    }
    return out;
}

}  // namespace rt
