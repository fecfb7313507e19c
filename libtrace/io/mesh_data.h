// Small pieces the importers share: float points as the RAW format stores them, triangles
// appended only when they have an area, and the classic Phong materials of OBJ and Assimp.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/aabb.h"
#include "scene/scene.h"

namespace rt {

using Point3f = std::array<float, 3>;

// Appends triangle (a, b, c) to model.triangleVertices unless its area is zero in float,
// the precision the model is stored in; returns false when it was dropped. The points
// must be finite (the importers reject files with NaN or infinite positions).
bool appendTriangle(Model& model, const Point3f& a, const Point3f& b, const Point3f& c);

// A triangle corner as a file gives it: its point and the per-vertex data the file has
// (each a pointer to that vertex's floats, or null).
struct Corner {
    Point3f point;
    const float* normal = nullptr;   // 3 floats
    const float* uv = nullptr;       // 2 floats, glTF's convention (v down the image)
    const float* color = nullptr;    // 3 floats, linear RGB
    const float* tangent = nullptr;  // 4 floats: x y z and the handedness w
};

// A mesh's per-vertex data as the importers read it: 3, 2 and 3 floats per vertex, each
// array empty when the mesh does not have it.
struct VertexData {
    std::vector<float> normals, uvs, colors, tangents;

    // The corner at vertex `v` of `points`, with the data there is for it.
    Corner corner(const std::vector<Point3f>& points, std::size_t v) const {
        const auto at = [v](const std::vector<float>& values, std::size_t n) {
            return values.empty() ? nullptr : &values[v * n];
        };
        return {points[v], at(normals, 3), at(uvs, 2), at(colors, 3), at(tangents, 4)};
    }
};

// appendTriangle with the corners' data appended to the model's per-corner arrays. An array
// starts with the first triangle that has the data; the triangles before it, and corners
// without it, get the neutral value (zero normal: flat; uv 0, 0; white).
bool appendTriangleWithData(Model& model, const Corner& a, const Corner& b, const Corner& c);

// Pads the model's per-corner arrays with neutral values to cover every triangle, and makes
// its normals unit length.
void finishCornerData(Model& model);

// The file `written` names relative to `folder`, found as tools on Windows and macOS would:
// as written if it exists, else with backslashes read as separators (OBJ files from Windows
// write `.\tex.jpg`) and each part matched regardless of ASCII case (3DS files name
// `CWALL02.JPG` for cwall02.jpg) when exactly one entry matches. As written if nothing does,
// so that the warning names what the file says.
std::filesystem::path locateBeside(const std::filesystem::path& folder, const std::string& written);

// An image texture that a model file names relative to its own folder (repeating, no transform),
// found by locateBeside.
Texture textureBeside(const std::string& modelPath, const std::string& file);

// Adds a texture to the scene; returns its index.
std::uint32_t addTexture(Scene& scene, Texture texture);

// A colour read from a file: NaN, infinite and negative channels read as 0, channels beyond
// kMaxColorValue (core/color.h) as kMaxColorValue.
Color fileColor(float r, float g, float b);

// rt's material from the classic Phong parameters of OBJ/MTL and Assimp materials
// (docs/conversion.md): colour = diffuse; specular = lum(specular), clamped to [0, 1];
// shininess clamped to [1, 10000], or rt's default when it is not positive and finite.
Material classicPhong(const Color& diffuse, const Color& specular, float shininess);

// A classic material's opacity below 1 (MTL's d, Assimp's opacity): 1 - opacity of the light
// passes, and the surface's own ambient and diffuse light fade by the opacity, as a dissolve
// blends them. With an index of refraction above 1 the material refracts as a solid, else the
// light passes straight on (thin). Opacity 1 (or not finite) changes nothing.
void applyOpacity(Material& m, float opacity, float ior);

// How a model's triangles turn against its vertex normals: a triangle faces away when its
// geometric normal (its corners counter-clockwise in front, as glTF and OBJ say) points
// against the sum of its corners' normals. Triangles without vertex normals are not counted.
struct WindingAgainstNormals {
    std::size_t facingAway = 0;
    std::size_t withNormals = 0;

    // Most triangles face away: the winding is inverted, and a single-sided material shows
    // the mesh's inside (rt-convert and rt-render --double-sided draw both sides).
    bool mostlyFacingAway() const { return facingAway * 2 > withNormals; }
};
WindingAgainstNormals windingAgainstNormals(const Model& model);

// Makes every material of the scene two-sided (ImportOptions::doubleSided, rt-convert and
// rt-render --double-sided): a model whose winding is inverted then shows its outside.
void makeDoubleSided(Scene& scene);

// Bounds of a model's triangles and spheres in its own space (empty for an empty model).
Aabb modelBounds(const Model& model);

}  // namespace rt
