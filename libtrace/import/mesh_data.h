// Small pieces the importers share: float points as the RAW format stores them, triangles
// appended only when they have an area, the classic Phong materials of OBJ and Assimp, and
// the names of materials and models, which the scene writer uses as identifiers and file names.
#pragma once

#include <array>
#include <set>
#include <string>

#include "core/aabb.h"
#include "scene/scene.h"

namespace rt {

using Point3f = std::array<float, 3>;

// Appends triangle (a, b, c) to model.triangleVertices unless its area is zero in float,
// the precision the model is stored in; returns false when it was dropped. The points
// must be finite (the importers reject files with NaN or infinite positions).
bool appendTriangle(Model& model, const Point3f& a, const Point3f& b, const Point3f& c);

// A colour read from a file: NaN, infinite and negative channels read as 0.
Color fileColor(float r, float g, float b);

// rt's material from the classic Phong parameters of OBJ/MTL and Assimp materials
// (docs/conversion.md): colour = diffuse; specular = lum(specular), clamped to [0, 1];
// shininess clamped to [1, 10000], or rt's default when it is not positive and finite.
Material classicPhong(const Color& diffuse, const Color& specular, float shininess);

// Bounds of a model's triangles and spheres in its own space (empty for an empty model).
Aabb modelBounds(const Model& model);

// Hands out names that are unique within one table and safe as XML attribute values and
// file names: letters, digits, '_', '-' and '.' are kept, anything else becomes '_'.
// A taken name gets "_2", "_3", ... appended.
class NameTable {
public:
    std::string claim(const std::string& wanted, const std::string& fallback);

private:
    std::set<std::string> used_;
};

}  // namespace rt
