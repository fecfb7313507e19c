#include "scene/crease_normals.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numeric>
#include <span>

namespace rt {

namespace {

using Key = std::array<std::uint32_t, 3>;  // a corner's position as bits (-0 as +0)

struct Face {
    Vec3 normal;                 // unit
    std::array<Real, 3> angles;  // at each corner, radians
};

Vec3 cornerOf(const Model& model, std::size_t corner) {
    const float* p = &model.triangleVertices[3 * corner];
    return {p[0], p[1], p[2]};
}

Key keyOf(const Model& model, std::size_t corner) {
    Key key;
    for (int a = 0; a < 3; ++a) key[a] = std::bit_cast<std::uint32_t>(model.triangleVertices[3 * corner + a] + 0.0f);
    return key;
}

Real angleBetween(const Vec3& a, const Vec3& b) { return std::atan2(length(cross(a, b)), dot(a, b)); }

std::vector<Face> facesOf(const Model& model) {
    std::vector<Face> faces(model.triangleCount());
    for (std::size_t t = 0; t < faces.size(); ++t) {
        const Vec3 p[3] = {cornerOf(model, 3 * t), cornerOf(model, 3 * t + 1), cornerOf(model, 3 * t + 2)};
        const Vec3 n = cross(p[1] - p[0], p[2] - p[0]);
        faces[t].normal = length(n) > 0 ? normalize(n) : Vec3{};
        for (int c = 0; c < 3; ++c) faces[t].angles[c] = angleBetween(p[(c + 1) % 3] - p[c], p[(c + 2) % 3] - p[c]);
    }
    return faces;
}

// The normal at each of `corners` (all at one point): the angle-weighted mean of the faces
// there within the crease angle of the corner's own face.
void smoothCorners(std::span<const std::size_t> corners, const std::vector<Face>& faces, Real minCosine,
                   std::vector<float>& normals) {
    for (const std::size_t corner : corners) {
        const Vec3 own = faces[corner / 3].normal;
        Vec3 sum;
        if (corners.size() > kMaxSmoothedCorners) {
            sum = own;
        } else {
            for (const std::size_t other : corners) {
                const Face& f = faces[other / 3];
                if (dot(own, f.normal) >= minCosine) sum += f.normal * f.angles[other % 3];
            }
        }
        const Real len = length(sum);
        const Vec3 n = len > 0 ? sum / len : own;
        for (int a = 0; a < 3; ++a) normals[3 * corner + a] = float(n[a]);
    }
}

}  // namespace

void addCreaseNormals(Model& model, double creaseDegrees) {
    if (!model.vertexNormals.empty() || model.triangleCount() == 0) return;
    const std::vector<Face> faces = facesOf(model);
    // Corners in order of their position, so that those at one point are neighbours.
    std::vector<std::size_t> corners(3 * faces.size());
    std::iota(corners.begin(), corners.end(), std::size_t(0));
    std::vector<Key> keys(corners.size());
    for (std::size_t c = 0; c < corners.size(); ++c) keys[c] = keyOf(model, c);
    std::sort(corners.begin(), corners.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
    // A tiny margin so that faces exactly at the crease angle (a cube's 90 degrees at 90) are smoothed.
    const Real minCosine = Real(std::cos(creaseDegrees * kPi / 180)) - Real(1e-6);
    model.vertexNormals.assign(9 * faces.size(), 0);
    for (std::size_t begin = 0; begin < corners.size();) {
        std::size_t end = begin + 1;
        while (end < corners.size() && keys[corners[end]] == keys[corners[begin]]) ++end;
        smoothCorners({corners.data() + begin, end - begin}, faces, minCosine, model.vertexNormals);
        begin = end;
    }
}

}  // namespace rt
