#include "scene/scene.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace rt {

namespace {

// Adds one instance of a model to `out`. A sphere under a non-uniform scale would be
// an ellipsoid, which the renderer has no primitive for: its radius takes the largest
// stretch of the transform.
std::size_t addInstance(const Model& model, const Instance& inst, Primitives& out) {
    std::size_t dropped = 0;
    const Transform& xf = inst.transform;
    const std::vector<float>& v = model.triangleVertices;
    for (std::size_t i = 0; i + 9 <= v.size(); i += 9) {
        const Triangle t{xf.point({v[i], v[i + 1], v[i + 2]}), xf.point({v[i + 3], v[i + 4], v[i + 5]}),
                         xf.point({v[i + 6], v[i + 7], v[i + 8]})};
        if (t.degenerate())
            ++dropped;
        else
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
    for (const Instance& inst : instances) dropped += addInstance(models[inst.model], inst, primitives);
    return dropped;
}

void Scene::dropDescription() {
    std::vector<Model>().swap(models);
    std::vector<Instance>().swap(instances);
    looseObjects = Primitives();
}

std::optional<std::uint32_t> Scene::findMaterial(const std::string& name) const {
    for (std::uint32_t i = 0; i < materials.size(); ++i)
        if (materials[i].name == name) return i;
    return std::nullopt;
}

void Scene::selectCamera(const std::string& nameOrIndex) {
    std::vector<Camera*> all{&camera};
    for (Camera& c : extraCameras) all.push_back(&c);
    const auto named = std::find_if(all.begin(), all.end(), [&](const Camera* c) { return c->name == nameOrIndex; });
    if (named != all.end()) return std::swap(camera, **named);
    std::string known;  // names come before numbers: a camera may be named "1"
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (std::to_string(i) == nameOrIndex) return std::swap(camera, *all[i]);
        known += (i ? ", " : "") + std::to_string(i) + (all[i]->name.empty() ? "" : " \"" + all[i]->name + "\"");
    }
    throw InputError("--camera " + nameOrIndex + ": the scene has no camera of that name or number (it has " + known +
                     ")");
}

}  // namespace rt
