// The scaffolding every importer (glTF, Assimp, OBJ) builds its scene with, so that models,
// materials, names and drop counts behave the same whichever format a file is in:
// - one Model per distinct mesh of the file, converted the first time it is asked for (the
//   importer's MeshKey says what a distinct mesh is: a glTF (mesh, primitive), an aiMesh, an
//   OBJ part), named uniquely and safely (scene/unique_names.h);
// - triangles without area dropped and counted once per model (ImportReport::droppedDegenerate)
//   and once per placement (droppedDegenerateInScene);
// - one Material per material of the file (MaterialKey), made the first time an instance uses it;
// - one Instance per placement of a model that kept triangles;
// - the models whose triangles mostly face away from the file's vertex normals, for a note.
// An importer reads its format and hands the assembly keys, corner points and materials; how to
// add one is in docs/architecture.md. Per-corner data (normals, texture coordinates, colours)
// comes with the corner points (Corner); meshes without normals get them by crease angle
// unless ImportOptions::flat.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "io/import.h"
#include "io/mesh_data.h"
#include "scene/crease_normals.h"
#include "scene/unique_names.h"

namespace rt {

// A converted mesh: its index in Scene::models (none when nothing was left of it) and how
// many degenerate triangles were dropped from it.
struct ConvertedMesh {
    std::optional<std::uint32_t> model;
    std::size_t dropped = 0;
};

// One Model being converted: triangles are appended when they have an area in float
// (appendTriangle) and counted as dropped when they have none.
class ModelBuilder {
public:
    explicit ModelBuilder(std::string name) { model_.name = std::move(name); }

    void reserveTriangles(std::size_t count) { model_.triangleVertices.reserve(count * 9); }

    void addTriangle(const Point3f& a, const Point3f& b, const Point3f& c) {
        if (!appendTriangle(model_, a, b, c)) ++dropped_;
    }
    void addTriangleWithData(const Corner& a, const Corner& b, const Corner& c) {
        if (!appendTriangleWithData(model_, a, b, c)) ++dropped_;
    }

    std::size_t dropped() const { return dropped_; }

    // The model, its per-corner arrays covering every triangle.
    Model take() {
        finishCornerData(model_);
        return std::move(model_);
    }

private:
    Model model_;
    std::size_t dropped_ = 0;
};

template <class MeshKey, class MaterialKey>
class SceneAssembly {
public:
    explicit SceneAssembly(ImportResult& out, const ImportOptions& options = {})
        : out_(out), creaseDegrees_(options.flat ? std::nullopt : std::optional(options.creaseDegrees)) {}

    ImportReport& report() { return out_.report; }

    // An empty model for a mesh the file calls `wanted` (`fallback` when nothing of that name
    // is left after safeName), under a name no other model of the scene has.
    ModelBuilder newModel(const std::string& wanted, const std::string& fallback) {
        return ModelBuilder(modelNames_.claim(safeName(wanted), fallback));
    }

    // Adds the built model to the scene unless it kept no triangle; its drops count once.
    ConvertedMesh addModel(ModelBuilder&& built) {
        ConvertedMesh converted{std::nullopt, built.dropped()};
        out_.report.droppedDegenerate += converted.dropped;
        Model model = built.take();
        if (model.triangleCount() == 0) return converted;
        if (windingAgainstNormals(model).mostlyFacingAway()) out_.report.modelsFacingAway.push_back(model.name);
        if (creaseDegrees_) addCreaseNormals(model, *creaseDegrees_);
        out_.scene.models.push_back(std::move(model));
        converted.model = std::uint32_t(out_.scene.models.size() - 1);
        return converted;
    }

    // The mesh `key`, converted by `convert()` (newModel, addTriangle, addModel; or {} for a
    // mesh with nothing to convert) the first time it is asked for.
    template <class Convert>
    ConvertedMesh mesh(const MeshKey& key, Convert convert) {
        const auto cached = meshes_.find(key);
        if (cached != meshes_.end()) return cached->second;
        return meshes_[key] = convert();
    }

    // Places `mesh` at `world` with the material index `materialOf()` gives, which is asked
    // for only when the mesh kept triangles (so unused materials are not made). The mesh's
    // drops count once more, for the scene.
    template <class MaterialOf>
    void place(const ConvertedMesh& mesh, MaterialOf materialOf, const Transform& world) {
        out_.report.droppedDegenerateInScene += mesh.dropped;
        if (mesh.model) out_.scene.instances.push_back({*mesh.model, materialOf(), world});
    }

    // Degenerate triangles dropped before they reach a model (an OBJ polygon's repeated
    // corners), from geometry that is placed exactly once.
    void dropDegenerate(std::size_t count) {
        out_.report.droppedDegenerate += count;
        out_.report.droppedDegenerateInScene += count;
    }

    // A face of one corner is a point, of two a line: rt renders neither; they are counted.
    void countFaceWithoutArea(std::size_t corners) {
        if (corners == 1) ++out_.report.droppedPoints;
        if (corners == 2) ++out_.report.droppedLines;
    }

    // The index in Scene::materials of material `key`, made by `make()` the first time: a
    // Material whose name is the file's; it is made unique and safe (`fallback` when nothing
    // of it is left).
    template <class Make>
    std::uint32_t material(const MaterialKey& key, const std::string& fallback, Make make) {
        const auto cached = materials_.find(key);
        if (cached != materials_.end()) return cached->second;
        Material m = make();
        m.name = materialNames_.claim(safeName(m.name), fallback);
        out_.scene.materials.push_back(std::move(m));
        return materials_[key] = std::uint32_t(out_.scene.materials.size() - 1);
    }

private:
    ImportResult& out_;
    std::optional<double> creaseDegrees_;  // none: meshes without normals stay flat
    std::map<MeshKey, ConvertedMesh> meshes_;
    std::map<MaterialKey, std::uint32_t> materials_;
    NameTable modelNames_;
    NameTable materialNames_;
};

}  // namespace rt
