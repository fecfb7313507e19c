// Triangle lists from the glTF primitive modes (glTF 2.0 specification, section 3.7.2.1):
// TRIANGLES as they are, TRIANGLE_STRIP and TRIANGLE_FAN unrolled with the winding the
// specification gives, so that front faces stay front faces.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace rt {

enum class Topology { Triangles, Strip, Fan };

// Three vertex indices per triangle, in the order (v0, v1, v2) of each triangle:
//   strip: triangle i = (v_i, v_{i+1+i%2}, v_{i+2-i%2})
//   fan:   triangle i = (v_{i+1}, v_{i+2}, v_0)
// A triangle list whose length is not a multiple of three loses the incomplete end.
std::vector<std::uint32_t> triangleCorners(Topology topology, std::span<const std::uint32_t> vertices);

}  // namespace rt
