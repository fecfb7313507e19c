// A scene as the thesis's XML format describes it (thesis 3.4.2): background, camera,
// materials, models instanced under transforms, loose spheres and triangles, lights.
// The description is kept (models in their own space, instances with their transforms)
// so that it can be written back; `primitives` is the flattened world-space geometry
// that accelerators and the renderer use.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/color.h"
#include "core/transform.h"
#include "geometry/primitives.h"
#include "scene/camera.h"
#include "scene/light.h"
#include "scene/metallic_roughness.h"
#include "scene/transmission.h"

namespace rt {

// A texture a material takes colour from (docs/scene-format.md, <textures>; rt extension).
// An image is looked up by the hit's texture coordinates, transformed as KHR_texture_transform
// does (scale, then rotate, then offset); a checker is a solid 3-D checkerboard of cubes of
// side `size` in world space, alternating colorA and colorB (thesis chapter 5's procedural textures).
struct Texture {
    enum class Kind { Image, Checker };
    enum class Wrap { Repeat, Clamp, Mirror };
    std::string name;
    Kind kind = Kind::Image;
    std::string file{};  // Image: as the scene gives it
    std::string path{};  // Image: the file to read (`file` resolved against the scene's folder)
    // Image: the encoded picture (PNG, JPEG, ...) when the scene holds it itself (embedded in a
    // .glb or as a data: URI, or an inline <texture>): read from memory; `file` is then only the
    // name it is saved under, its extension telling the format; `path` is empty.
    std::shared_ptr<const std::vector<std::uint8_t>> embedded{};
    Wrap wrapS = Wrap::Repeat, wrapT = Wrap::Repeat;
    std::array<float, 2> offset{0, 0}, scale{1, 1};
    float rotation = 0;  // radians
    Color colorA{1, 1, 1}, colorB{0, 0, 0};
    float size = 1;
};

// The largest offset, scale and rotation of a texture's coordinate transform and the largest
// normal-map scale, as every reader (XML, glTF's KHR_texture_transform, OBJ's -o, -s and -bm)
// holds them: a million repeats or radians, where float texture coordinates have long lost every
// texel; beyond float they made NaN.
inline constexpr double kMaxTextureTransform = 1e6;

// The farthest from the origin a scene file's loose primitive may reach: a sphere at 1e300 made
// every ray's squared distance to it infinite and vanished without a word; 1e15 squared still
// fits a float.
inline constexpr double kMaxCoordinate = 1e15;

// The Phong coefficients of thesis 2.1.3 and the glossy spread of thesis 2.6.2: the Whitted
// tracer's terms (render/materials/phong.h). The path tracer renders them through
// metallicRoughnessOf (scene/metallic_roughness.h) when the material has no factors of its own.
struct PhongTerms {
    float ambient = 0.1f;     // k_a
    float diffuse = 0.9f;     // k_d
    float specular = 0.0f;    // k_s
    float shininess = 20.0f;  // n, the sharpness of the highlight
    float reflection = 0.0f;  // mirror reflectivity, 0-1
    float spread = 0.0f;      // sigma of the glossy reflection lobe (thesis 2.6.2), radians
};

// KHR_materials_clearcoat: a clear layer of ior 1.5 over the material (render/materials/clearcoat_bsdf.h;
// the path tracer only). Weight 0: no coat.
struct Clearcoat {
    float weight = 0;     // clearcoatFactor, 0-1
    float roughness = 0;  // clearcoatRoughnessFactor, the coat's GGX roughness, 0-1
};

// rt extension: a tangent-space normal map in glTF's convention (render/normal_map.h).
struct NormalMap {
    std::optional<std::uint32_t> texture{};  // index in Scene::textures; none: the surface's own normals
    float scale = 1;                         // multiplies the texel's x and y (glTF's normalTexture.scale)
};

// Light the surface gives off (rt extension), added to what it reflects; only the path tracer lights
// other surfaces with it. From XML's emission and emission_texture, glTF's emissiveFactor (times
// KHR_materials_emissive_strength) and emissiveTexture, MTL's Ke and map_Ke, Assimp's emissive colour.
struct Emission {
    Color color{0, 0, 0};
    std::optional<std::uint32_t> texture{};  // index in Scene::textures; multiplies the colour
};

// The path tracer's glTF metallic-roughness terms (scene/metallic_roughness.h), as PhongTerms are the
// Whitted tracer's (which takes only its glossy spread from a texture over factors: glossySpread);
// from glTF's pbrMetallicRoughness, XML's metallic, roughness, specular_factor and
// metallic_roughness_texture. Either may be given without the other: factors without a texture are
// uniform, a texture without factors scales those metallicRoughnessOf makes from the Phong terms.
struct PbrTerms {
    // The material's own factors; none: the path tracer follows a rule from the Phong terms.
    std::optional<MetallicRoughness> factors{};
    // glTF's metallicRoughnessTexture: its blue channel scales metallic, its green roughness.
    std::optional<std::uint32_t> texture{};
};

// Cut-outs (rt extension; glTF's alphaMode MASK and BLEND and base colour alpha, OBJ's map_d or
// map_Kd's alpha, XML's alpha_cutoff, alpha and alpha_texture): where the opacity, alpha times the
// texture's alpha at the hit, is below the cut-off, rays pass through the surface. A texture that
// is the colour texture gives its alpha channel (1 without one); any other is a mask: its alpha
// channel, or its first channel when it has none.
struct Opacity {
    std::optional<float> cutoff{};  // set: the material is a cut-out
    float alpha = 1;
    std::optional<std::uint32_t> texture{};  // index in Scene::textures
};

// Surface properties (thesis 3.3.2) and the Phong coefficients of thesis 2.1.3.
struct Material {
    std::string name;
    // The colour every shading model starts from: Phong's k_d and k_a colour, the metallic-roughness
    // base colour.
    Color color{1, 1, 1};
    PhongTerms phong{};
    // rt extension: the colour is multiplied by a texture's.
    std::optional<std::uint32_t> colorTexture{};  // index in Scene::textures
    Emission emission{};
    PbrTerms pbr{};
    Clearcoat clearcoat{};
    Opacity opacity{};
    NormalMap normalMap{};
    Transmission transmission{};  // rt extension: glass (scene/transmission.h)
    // rt extension, glTF's doubleSided: false makes the material single-sided, and every ray
    // passes through its back (render/material_filter.h). The front is the side from which a
    // triangle's corners run counter-clockwise in its model's own space, or a sphere's outside.
    bool doubleSided = true;
};

// A model loaded once and instanced many times (thesis 3.4.3). Geometry is kept in
// float, as the RAW format stores it.
struct Model {
    enum class Format { Raw, Max3ds };
    std::string name;
    std::string file;  // as written in the scene; empty when the data is inline
    Format format = Format::Raw;
    std::vector<float> triangleVertices;  // 9 floats per triangle
    std::vector<float> sphereData;        // 4 floats per sphere: centre, radius
    // Per-corner shading data of the triangles, in the corners' order; each is empty or
    // holds every triangle's (docs/scene-format.md, the RAW extension).
    std::vector<float> vertexNormals;  // 9 floats per triangle: unit normals, or zeros for a flat triangle
    std::vector<float> vertexUvs;      // 6 floats per triangle: texture coordinates u, v
    std::vector<float> vertexColors;   // 9 floats per triangle: linear RGB
    // 12 floats per triangle: a file's tangents x y z and handedness w (glTF's TANGENT), or
    // zeros where the normal map's tangents are to be generated (geometry/tangents.h).
    std::vector<float> vertexTangents;

    std::size_t triangleCount() const { return triangleVertices.size() / 9; }
    std::size_t sphereCount() const { return sphereData.size() / 4; }
};

// rt extension: the path tracer's sky as an equirectangular image (render/lights/environment_light.h,
// <environment> in docs/scene-format.md).
struct Environment {
    std::uint32_t texture = 0;  // an image texture
    float intensity = 1;        // scales its radiance
    float rotation = 0;         // degrees about +y, counter-clockwise seen from above
};

struct Instance {
    std::uint32_t model = 0;
    std::uint32_t material = 0;
    Transform transform;
};

struct Scene {
    Color background{0, 0, 0};
    Camera camera;                     // the camera rendered: the file's first, or the one --camera picked
    std::vector<Camera> extraCameras;  // rt extension: the file's other cameras, in file order
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Model> models;
    std::vector<Instance> instances;
    Primitives looseObjects;  // spheres, triangles and quads placed directly, in world space
    std::vector<Light> lights;
    // rt extension: the path tracer's sky; none: the background colour
    std::optional<Environment> environment{};

    Primitives primitives;              // everything, in world space: looseObjects, then each instance
    std::size_t droppedDegenerate = 0;  // by the loader and by flatten()
    std::vector<std::string> warnings;

    // Rebuilds `primitives` from the loose objects and the instances. Degenerate
    // primitives (zero area, radius <= 0, non-finite) are dropped; returns how many.
    std::size_t flatten();
    // Frees the models and instances once `primitives` is built, for tools that only trace
    // rays: a model's own copy of its geometry would otherwise add 36 bytes per triangle.
    void dropDescription();
    std::optional<std::uint32_t> findMaterial(const std::string& name) const;
    // The material of primitives[prim]: a default one when the scene has none (scenes built in code).
    const Material& materialOf(std::uint32_t prim) const;
    // Makes the camera named `nameOrIndex`, or numbered so (0 is the first in the file), the one
    // rendered (the first takes its place among the others), its headlights with it. Throws
    // rt::InputError naming the cameras there are.
    void selectCamera(const std::string& nameOrIndex);
    // Puts every headlight (Light::headlight) at the camera's origin: after anything that moves
    // the camera, before a render.
    void placeHeadlights();
    // Removes the headlights (rt-render --light and --no-default-light replace them).
    void dropHeadlights();
    // Whether a material emits light (the path tracer's area lights).
    bool hasEmissiveMaterial() const;
};

}  // namespace rt
