#include "io/mesh_data.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>

#include "core/vec3.h"
#include "os/sandbox.h"

namespace rt {

bool appendTriangle(Model& model, const Point3f& a, const Point3f& b, const Point3f& c) {
    // The cross product in double of the float edges: exactly zero only for collinear
    // or coincident float points, the triangles a ray tracer can never hit.
    const double e1[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
    const double e2[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) return false;
    for (const Point3f* p : {&a, &b, &c})
        model.triangleVertices.insert(model.triangleVertices.end(), p->begin(), p->end());
    return true;
}

namespace {

// One per-corner array of a model: its floats per corner and its neutral value.
struct CornerArray {
    std::vector<float> Model::*values;
    const float* Corner::*source;
    std::size_t floats;
    float neutral;
};
constexpr CornerArray kCornerArrays[] = {
    {&Model::vertexNormals, &Corner::normal, 3, 0},
    {&Model::vertexUvs, &Corner::uv, 2, 0},
    {&Model::vertexColors, &Corner::color, 3, 1},
    {&Model::vertexTangents, &Corner::tangent, 4, 0},
};

}  // namespace

bool appendTriangleWithData(Model& model, const Corner& a, const Corner& b, const Corner& c) {
    if (!appendTriangle(model, a.point, b.point, c.point)) return false;
    const std::size_t before = model.triangleCount() - 1;
    for (const CornerArray& array : kCornerArrays) {
        std::vector<float>& to = model.*array.values;
        const bool has = a.*array.source || b.*array.source || c.*array.source;
        if (!has && to.empty()) continue;
        to.resize(before * 3 * array.floats, array.neutral);
        for (const Corner* corner : {&a, &b, &c}) {
            const float* from = corner->*array.source;
            for (std::size_t i = 0; i < array.floats; ++i) to.push_back(from ? from[i] : array.neutral);
        }
    }
    return true;
}

void finishCornerData(Model& model) {
    for (const CornerArray& array : kCornerArrays) {
        std::vector<float>& values = model.*array.values;
        if (!values.empty()) values.resize(model.triangleCount() * 3 * array.floats, array.neutral);
    }
    // Files store normals of any length (quantized, scaled); zero ones stay zero: flat.
    std::vector<float>& n = model.vertexNormals;
    for (std::size_t i = 0; i + 3 <= n.size(); i += 3) {
        const double len = std::sqrt(double(n[i]) * n[i] + double(n[i + 1]) * n[i + 1] + double(n[i + 2]) * n[i + 2]);
        if (len > 0)
            for (std::size_t a = 0; a < 3; ++a) n[i + a] = float(n[i + a] / len);
    }
}

namespace {

// The entry of `folder` whose name is `name` but for ASCII case, if there is exactly one.
std::optional<std::filesystem::path> entryIgnoringCase(const std::filesystem::path& folder, const std::string& name) {
    const auto lower = [](std::string s) {
        for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    const std::string wanted = lower(name);
    std::optional<std::filesystem::path> found;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (lower(it->path().filename().string()) != wanted) continue;
        if (found) return std::nullopt;  // two spellings: neither is chosen
        found = it->path();
    }
    return found;
}

}  // namespace

std::filesystem::path locateBeside(const std::filesystem::path& folder, const std::string& written) {
    const std::filesystem::path asWritten = folder / written;
    std::error_code ec;
    if (std::filesystem::exists(asWritten, ec)) return asWritten;
    std::string slashed = written;
    std::replace(slashed.begin(), slashed.end(), '\\', '/');
    std::filesystem::path path = folder;
    for (const std::filesystem::path& part : std::filesystem::path(slashed).relative_path()) {
        if (part == ".") continue;
        std::filesystem::path next = path / part;
        if (!std::filesystem::exists(next, ec) && part != "..") {
            const std::optional<std::filesystem::path> other = entryIgnoringCase(path, part.string());
            if (!other) return asWritten;
            next = *other;
        }
        path = std::move(next);
    }
    return std::filesystem::exists(path, ec) ? path : asWritten;
}

Texture textureBeside(const std::string& modelPath, const std::string& file) {
    Texture t;
    const std::filesystem::path path = locateBeside(std::filesystem::path(modelPath).parent_path(), file);
    t.name = path.stem().string();
    t.path = path.string();
    t.file = t.path;
    requireInsideSandbox(t.path, "texture " + file, modelPath);
    return t;
}

std::uint32_t addTexture(Scene& scene, Texture texture) {
    scene.textures.push_back(std::move(texture));
    return std::uint32_t(scene.textures.size() - 1);
}

Color fileColor(float r, float g, float b) {
    const auto channel = [](float v) { return std::isfinite(v) ? std::clamp(v, 0.0f, float(kMaxColorValue)) : 0.0f; };
    return {channel(r), channel(g), channel(b)};
}

Material classicPhong(const Color& diffuse, const Color& specular, float shininess) {
    Material m;
    m.color = diffuse;
    m.phong.specular = std::clamp(luminance(specular), 0.0f, 1.0f);
    if (shininess > 0 && std::isfinite(shininess)) m.phong.shininess = std::clamp(shininess, 1.0f, 10000.0f);
    return m;
}

void applyOpacity(Material& m, float opacity, float ior) {
    if (!std::isfinite(opacity) || opacity >= 1) return;
    opacity = std::max(opacity, 0.0f);
    const bool solid = std::isfinite(ior) && ior > 1;
    m.transmission = {.weight = 1 - opacity, .ior = solid ? ior : 1.0f, .thin = !solid};
    m.phong.ambient *= opacity;
    m.phong.diffuse *= opacity;
}

WindingAgainstNormals windingAgainstNormals(const Model& model) {
    WindingAgainstNormals w;
    const std::vector<float>&v = model.triangleVertices, &n = model.vertexNormals;
    if (n.size() != v.size()) return w;  // no vertex normals (or not one per corner)
    const auto at = [](const std::vector<float>& a, std::size_t i) { return Vec3(a[i], a[i + 1], a[i + 2]); };
    for (std::size_t t = 0; t + 9 <= v.size(); t += 9) {
        const Vec3 summed = at(n, t) + at(n, t + 3) + at(n, t + 6);
        if (summed == Vec3(0, 0, 0)) continue;  // a flat triangle: no normals of its own
        ++w.withNormals;
        const Vec3 geometric = cross(at(v, t + 3) - at(v, t), at(v, t + 6) - at(v, t));
        w.facingAway += dot(geometric, summed) < 0;
    }
    return w;
}

void makeDoubleSided(Scene& scene) {
    for (Material& m : scene.materials) m.doubleSided = true;
}

Aabb modelBounds(const Model& model) {
    Aabb box;
    const std::vector<float>& v = model.triangleVertices;
    for (std::size_t i = 0; i + 3 <= v.size(); i += 3) box.extend(Vec3(v[i], v[i + 1], v[i + 2]));
    const std::vector<float>& s = model.sphereData;  // RAW models may hold spheres
    for (std::size_t i = 0; i + 4 <= s.size(); i += 4) {
        const Vec3 centre(s[i], s[i + 1], s[i + 2]), radius(s[i + 3], s[i + 3], s[i + 3]);
        box.extend(centre - radius);
        box.extend(centre + radius);
    }
    return box;
}

}  // namespace rt
