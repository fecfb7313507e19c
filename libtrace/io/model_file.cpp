#include "io/model_file.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/text.h"
#include "io/assimp_contained.h"
#include "io/raw_model.h"
#include "os/input_file.h"

namespace rt {
namespace {

// Appends the triangles of every mesh under `node`, in model space: each node's
// transform is composed with its parents' (Assimp's matrices act on column vectors).
void appendNodeTriangles(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent, Model& model) {
    const aiMatrix4x4 toModel = parent * node.mTransformation;
    for (unsigned m = 0; m < node.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[m]];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines have no surface
            for (unsigned k = 0; k < 3; ++k) {
                const aiVector3D p = toModel * mesh.mVertices[face.mIndices[k]];
                model.triangleVertices.insert(model.triangleVertices.end(), {p.x, p.y, p.z});
            }
        }
    }
    for (unsigned c = 0; c < node.mNumChildren; ++c) appendNodeTriangles(scene, *node.mChildren[c], toModel, model);
}

// Assimp picks its importer from the file name and content; a file that is not 3DS could
// reach an importer with known crashes on bad input (glTF: docs/conversion.md). So the bytes go
// to Assimp from memory with a "3ds" hint, and only after the 3DS magic is checked.
Model load3ds(const std::string& path) {
    const std::string bytes = readInputFile(path);
    const auto fail = [&](const std::string& why) { return InputError(path + ": cannot read 3ds model: " + why); };
    if (bytes.empty()) throw fail("the file is empty");
    if (bytes.size() < 6 || bytes[0] != 0x4d || bytes[1] != 0x4d)
        throw fail("not a 3DS file (no 0x4D4D main chunk at byte 0)");
    const std::unique_ptr<aiScene> scene = readContained(path, bytes.size(), [&](Assimp::Importer& reader) {
        // ValidateDataStructure rejects out-of-range indices before we follow them.
        const aiScene* read = reader.ReadFileFromMemory(bytes.data(), bytes.size(),
                                                        aiProcess_Triangulate | aiProcess_ValidateDataStructure, "3ds");
        if (!read || !read->mRootNode || (read->mFlags & AI_SCENE_FLAGS_INCOMPLETE))
            throw fail(reader.GetErrorString());
        return read;
    });
    Model model;
    appendNodeTriangles(*scene, *scene->mRootNode, aiMatrix4x4(), model);
    const auto bad = std::find_if(model.triangleVertices.begin(), model.triangleVertices.end(),
                                  [](float v) { return !std::isfinite(v); });
    if (bad != model.triangleVertices.end())
        throw fail("NaN or infinite vertex coordinate in triangle " +
                   std::to_string((bad - model.triangleVertices.begin()) / 9));
    return model;
}

}  // namespace

std::optional<Model::Format> modelFormatFromName(const std::string& name) {
    const std::string n = lowerCase(name);
    if (n == "raw") return Model::Format::Raw;
    if (n == "3ds") return Model::Format::Max3ds;
    return std::nullopt;
}

std::optional<Model::Format> modelFormatFromExtension(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    return ext.empty() ? std::nullopt : modelFormatFromName(ext.substr(1));
}

const char* modelFormatName(Model::Format format) { return format == Model::Format::Raw ? "raw" : "3ds"; }

Model readModelFile(const std::string& path, Model::Format format) {
    return format == Model::Format::Raw ? readRawFile(path) : load3ds(path);
}

}  // namespace rt
