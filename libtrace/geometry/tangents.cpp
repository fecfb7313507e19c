#include "geometry/tangents.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace rt {

bool uvDerivatives(const Triangle& tri, const CornerUvs& uv, Vec3& dpdu, Vec3& dpdv, Real* uvArea) {
    const Vec3 e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0;
    const auto& t = uv.values;
    const Real du1 = t[2] - t[0], dv1 = t[3] - t[1], du2 = t[4] - t[0], dv2 = t[5] - t[1];
    const Real det = du1 * dv2 - du2 * dv1;
    if (!(std::abs(det) > 0)) return false;
    dpdu = (e1 * dv2 - e2 * dv1) / det;
    dpdv = (e2 * du1 - e1 * du2) / det;
    if (uvArea) *uvArea = det;
    return true;
}

namespace {

// A triangle's texture frame; `mirrored` where its texture-space area is negative (the texture
// is mirrored). False for a triangle whose texture coordinates are degenerate.
struct FaceFrame {
    Vec3 dpdu, dpdv;
    bool mirrored = false;
};

bool faceFrame(const Triangle& tri, const CornerUvs& uv, FaceFrame& f) {
    Real det = 0;
    if (!uvDerivatives(tri, uv, f.dpdu, f.dpdv, &det)) return false;
    f.mirrored = det < 0;
    return true;
}

Vec3 cornerPoint(const Triangle& tri, int c) { return c == 0 ? tri.p0 : c == 1 ? tri.p1 : tri.p2; }

// The angle of the triangle at corner c, MikkTSpace's weight.
Real cornerAngle(const Triangle& tri, int c) {
    const Vec3 p = cornerPoint(tri, c);
    const Vec3 a = cornerPoint(tri, (c + 1) % 3) - p, b = cornerPoint(tri, (c + 2) % 3) - p;
    const Real la = length(a), lb = length(b);
    return la > 0 && lb > 0 ? std::acos(std::clamp(dot(a, b) / (la * lb), Real(-1), Real(1))) : 0;
}

// v without its part along the unit vector n, unit (zero if nothing is left).
Vec3 orthogonalTo(const Vec3& v, const Vec3& n) {
    const Vec3 o = v - n * dot(n, v);
    const Real len = length(o);
    return len > 0 ? o / len : Vec3{};
}

// A vertex as MikkTSpace welds it: position, normal, texture coordinates and orientation.
using VertexKey = std::array<float, 9>;
struct VertexKeyHash {
    std::size_t operator()(const VertexKey& k) const {
        return std::hash<std::string_view>()(std::string_view(reinterpret_cast<const char*>(k.data()), sizeof k));
    }
};
struct Accumulated {
    Vec3 tangent, bitangent;
};

struct Corner {
    VertexKey key;
    Vec3 normal;
};

class TangentBuilder {
public:
    TangentBuilder(Primitives& prims, const std::function<bool(std::uint32_t)>& wanted) : prims_(prims) {
        const TriangleShading& shading = prims.triangleShading();
        for (std::uint32_t i = 0; i < std::uint32_t(shading.uvs.size()); ++i)
            if (shading.uvs.find(i) && wanted(prims.material(i)) && !fromFile(shading, i)) triangles_.push_back(i);
    }

    void run() {
        for (std::uint32_t i : triangles_) accumulate(i);
        for (std::uint32_t i : triangles_) store(i);
    }

private:
    // Whether triangle i has its tangents already (a file's: a handedness of +1 or -1, not the 0 of none).
    static bool fromFile(const TriangleShading& shading, std::uint32_t i) {
        const CornerTangents* t = shading.tangents.find(i);
        return t && t->values[3] != 0;
    }

    Corner corner(std::uint32_t i, int c, bool mirrored) const {
        const Triangle& tri = prims_.all<Triangle>()[i];
        const CornerNormals* normals = prims_.triangleShading().normals.find(i);
        Vec3 n = normals ? normals->corner(c) : Vec3{};
        if (!(length(n) > 0)) n = tri.normal(tri.p0);  // a flat triangle
        const Vec3 p = cornerPoint(tri, c);
        const auto& uv = prims_.triangleShading().uvs.find(i)->values;
        return {{float(p.x), float(p.y), float(p.z), float(n.x), float(n.y), float(n.z), uv[2 * c], uv[2 * c + 1],
                 mirrored ? -1.0f : 1.0f},
                n};
    }

    void accumulate(std::uint32_t i) {
        const Triangle& tri = prims_.all<Triangle>()[i];
        FaceFrame f;
        if (!faceFrame(tri, *prims_.triangleShading().uvs.find(i), f)) return;
        for (int c = 0; c < 3; ++c) {
            const Corner k = corner(i, c, f.mirrored);
            const Real weight = cornerAngle(tri, c);
            Accumulated& a = sums_[k.key];
            a.tangent += orthogonalTo(f.dpdu, k.normal) * weight;
            a.bitangent += orthogonalTo(f.dpdv, k.normal) * weight;
        }
    }

    // The bitangent w * cross(n, t) points up the image, along -dP/dv.
    void store(std::uint32_t i) {
        FaceFrame f;
        faceFrame(prims_.all<Triangle>()[i], *prims_.triangleShading().uvs.find(i), f);
        CornerTangents out;
        for (int c = 0; c < 3; ++c) {
            const Corner k = corner(i, c, f.mirrored);
            const auto found = sums_.find(k.key);
            const Accumulated a = found != sums_.end() ? found->second : Accumulated{};
            Vec3 t = orthogonalTo(a.tangent, k.normal);
            if (!(length(t) > 0))
                t = orthogonalTo(std::abs(k.normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}, k.normal);
            const float w = dot(cross(k.normal, t), a.bitangent) > 0 ? -1.0f : 1.0f;
            for (int a3 = 0; a3 < 3; ++a3) out.values[4 * c + a3] = float(t[a3]);
            out.values[4 * c + 3] = w;
        }
        prims_.triangleShading().tangents.set(i, out);
    }

    Primitives& prims_;
    std::vector<std::uint32_t> triangles_;
    std::unordered_map<VertexKey, Accumulated, VertexKeyHash> sums_;
};

}  // namespace

void generateTangents(Primitives& prims, const std::function<bool(std::uint32_t material)>& wanted) {
    TangentBuilder(prims, wanted).run();
}

}  // namespace rt
