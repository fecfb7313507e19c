#include "import/mesh_data.h"

#include <algorithm>
#include <cmath>

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

Color fileColor(float r, float g, float b) {
    const auto channel = [](float v) { return std::isfinite(v) ? std::max(v, 0.0f) : 0.0f; };
    return {channel(r), channel(g), channel(b)};
}

Material classicPhong(const Color& diffuse, const Color& specular, float shininess) {
    Material m;
    m.color = diffuse;
    m.specular = std::clamp(luminance(specular), 0.0f, 1.0f);
    if (shininess > 0 && std::isfinite(shininess)) m.shininess = std::clamp(shininess, 1.0f, 10000.0f);
    return m;
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
