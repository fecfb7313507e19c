// Every other format Assimp reads (3DS, PLY, STL, FBX, DAE, NFF, ...); glTF and OBJ have their own importers.
#pragma once

#include <string>

#include "io/import.h"

struct aiScene;

namespace rt {

// Reads the file with aiProcess_Triangulate and aiProcess_ValidateDataStructure only (no
// post-processing that joins meshes, so instancing survives), with Assimp's glTF importers
// removed (they abort the process on some broken files; glTF goes through tinygltf). The node
// tree gives the instances (world = parent * local), each aiMesh one Model, aiMaterial the
// diffuse colour, specular, shininess and reflectivity, aiCamera and aiLight the camera and
// lights (3DS cameras from the file's own chunks, import/camera_3ds.h). The root transform
// follows rootTransform, knowing which formats Assimp turns Y-up itself. Camera and light
// defaults are left to the caller. Throws rt::InputError.
ImportResult importAssimp(const std::string& path, const ImportOptions& options);

// The second half of importAssimp: the scene from what Assimp read of `path` (in a child process,
// import/assimp_contained.h) with the importer named `format`. Apart for the fuzz target
// fuzz/assimp_reply_fuzz.cpp, which gives it whatever a reply can hold.
ImportResult importAssimpScene(const aiScene& scene, const std::string& path, const std::string& format,
                               const ImportOptions& options);

}  // namespace rt
