#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.h"
#include "geometry/tangents.h"

namespace rt {

namespace {

// Whether `xf` turns a right-handed frame into a left-handed one (a negative determinant).
bool mirrors(const Transform& xf) {
    return dot(cross(xf.vector({1, 0, 0}), xf.vector({0, 1, 0})), xf.vector({0, 0, 1})) < 0;
}

// Triangle `i`'s values from one of a model's per-corner arrays, corners p1 and p2 swapped
// when `reversed` (the triangle's winding is).
template <class T>
T cornerValues(const std::vector<float>& from, std::size_t i, bool reversed = false) {
    T to;
    std::copy_n(from.begin() + std::ptrdiff_t(i * to.values.size()), to.values.size(), to.values.begin());
    const std::size_t n = to.values.size() / 3;  // floats per corner
    if (reversed) std::swap_ranges(to.values.begin() + n, to.values.begin() + 2 * n, to.values.begin() + 2 * n);
    return to;
}

// The normals of triangle `i` placed by `xf` (inverse transpose, renormalised); zeros stay zeros.
CornerNormals placedNormals(const Model& model, std::size_t i, const Transform& xf, bool reversed) {
    CornerNormals n = cornerValues<CornerNormals>(model.vertexNormals, i, reversed);
    for (int c = 0; c < 3; ++c) {
        const Vec3 placed = xf.normal(n.corner(c));
        const Real len = length(placed);
        if (!(len > 0)) continue;
        for (int a = 0; a < 3; ++a) n.values[3 * c + a] = float(placed[a] / len);
    }
    return n;
}

// The file's tangents of triangle `i` placed by `xf`, or none where they are zero (to be
// generated). A mirroring transform turns the bitangent w * cross(n, t) the other way, as it
// does the image's up direction: w changes sign.
std::optional<CornerTangents> placedTangents(const Model& model, std::size_t i, const Transform& xf, bool reversed) {
    CornerTangents t = cornerValues<CornerTangents>(model.vertexTangents, i, reversed);
    const bool mirrored = mirrors(xf);
    for (int c = 0; c < 3; ++c) {
        float* corner = &t.values[4 * std::size_t(c)];
        const Vec3 placed = xf.vector({corner[0], corner[1], corner[2]});
        const Real len = length(placed);
        if (!(len > 0) || corner[3] == 0) return std::nullopt;
        for (int a = 0; a < 3; ++a) corner[a] = float(placed[a] / len);
        corner[3] = (corner[3] < 0) != mirrored ? -1.0f : 1.0f;
    }
    return t;
}

// Gives the triangle just added as number `index` the model's shading data for its triangle `i`.
void addShading(const Model& model, std::size_t i, const Transform& xf, bool reversed, std::size_t index,
                TriangleShading& to) {
    if (!model.vertexNormals.empty()) to.normals.set(index, placedNormals(model, i, xf, reversed));
    if (!model.vertexUvs.empty()) to.uvs.set(index, cornerValues<CornerUvs>(model.vertexUvs, i, reversed));
    if (!model.vertexColors.empty()) to.colors.set(index, cornerValues<CornerColors>(model.vertexColors, i, reversed));
    if (!model.vertexTangents.empty())
        if (const std::optional<CornerTangents> t = placedTangents(model, i, xf, reversed)) to.tangents.set(index, *t);
}

// Adds one instance of a model to `out`. A sphere under a non-uniform scale would be
// an ellipsoid, which the renderer has no primitive for: its radius takes the largest
// stretch of the transform. A mirroring transform turns the triangles' winding round; for a
// single-sided material, whose front the winding tells, the corners p1 and p2 are swapped to
// keep the model's front in front (as glTF orients a mesh under a negative determinant).
// Two-sided materials keep the corners as they are, so their scenes render as before.
std::size_t addInstance(const Model& model, const Instance& inst, bool singleSided, Primitives& out) {
    std::size_t dropped = 0;
    const Transform& xf = inst.transform;
    const bool reversed = singleSided && mirrors(xf);
    const int second = reversed ? 6 : 3, third = reversed ? 3 : 6;  // offsets of the corners placed as p1, p2
    const std::vector<float>& v = model.triangleVertices;
    for (std::size_t i = 0; i < model.triangleCount(); ++i) {
        const float* c = &v[9 * i];
        const Triangle t{xf.point({c[0], c[1], c[2]}), xf.point({c[second], c[second + 1], c[second + 2]}),
                         xf.point({c[third], c[third + 1], c[third + 2]})};
        if (t.degenerate()) {
            ++dropped;
            continue;
        }
        addShading(model, i, xf, reversed, out.count<Triangle>(), out.triangleShading());
        out.add<Triangle>(t, inst.material);
    }
    const std::vector<float>& s = model.sphereData;
    const Real radiusScale = xf.maxScale();
    for (std::size_t i = 0; i + 4 <= s.size(); i += 4) {
        const Sphere sp{xf.point({s[i], s[i + 1], s[i + 2]}), s[i + 3] * radiusScale};
        if (sp.degenerate())
            ++dropped;
        else
            out.add<Sphere>(sp, inst.material);
    }
    return dropped;
}

}  // namespace

std::size_t Scene::flatten() {
    primitives = Primitives();
    std::size_t triangles = looseObjects.count<Triangle>();
    for (const Instance& inst : instances) triangles += models[inst.model].triangleCount();
    primitives.reserve<Triangle>(triangles);
    primitives.append(looseObjects);
    std::size_t dropped = 0;
    for (const Instance& inst : instances) {
        const bool singleSided = inst.material < materials.size() && !materials[inst.material].doubleSided;
        dropped += addInstance(models[inst.model], inst, singleSided, primitives);
    }
    if (std::any_of(materials.begin(), materials.end(), [](const Material& m) { return m.normalMap.texture; }))
        generateTangents(primitives,
                         [&](std::uint32_t m) { return m < materials.size() && materials[m].normalMap.texture; });
    return dropped;
}

void Scene::placeHeadlights() {
    for (Light& light : lights)
        if (light.headlight) light.position = camera.origin;
}

void Scene::dropHeadlights() {
    std::erase_if(lights, [](const Light& light) { return light.headlight; });
}

bool Scene::hasEmissiveMaterial() const {
    return std::any_of(materials.begin(), materials.end(),
                       [](const Material& m) { return m.emission.color != Color{}; });
}

void Scene::dropDescription() {
    std::vector<Model>().swap(models);
    std::vector<Instance>().swap(instances);
    looseObjects = Primitives();
}

const Material& Scene::materialOf(std::uint32_t prim) const {
    static const Material fallback;
    const std::uint32_t id = primitives.material(prim);
    return id < materials.size() ? materials[id] : fallback;
}

std::optional<std::uint32_t> Scene::findMaterial(const std::string& name) const {
    for (std::uint32_t i = 0; i < materials.size(); ++i)
        if (materials[i].name == name) return i;
    return std::nullopt;
}

void Scene::selectCamera(const std::string& nameOrIndex) {
    std::vector<Camera*> all{&camera};
    for (Camera& c : extraCameras) all.push_back(&c);
    const auto take = [this](Camera& chosen) {
        std::swap(camera, chosen);
        placeHeadlights();
    };
    const auto named = std::find_if(all.begin(), all.end(), [&](const Camera* c) { return c->name == nameOrIndex; });
    if (named != all.end()) return take(**named);
    std::string known;  // names come before numbers: a camera may be named "1"
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (std::to_string(i) == nameOrIndex) return take(*all[i]);
        known += (i ? ", " : "") + std::to_string(i) + (all[i]->name.empty() ? "" : " \"" + all[i]->name + "\"");
    }
    throw InputError("--camera " + nameOrIndex + ": the scene has no camera of that name or number (" +
                     (all.size() == 1 ? "its one camera: " : "its cameras: ") + known + ")");
}

}  // namespace rt
