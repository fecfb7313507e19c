// The reply of the contained Assimp read (import/assimp_contained.h): the child process writes
// what rt's importers read of an aiScene, and nothing else, in a small binary format of rt's
// own; the tool reads it back into an aiScene of its own making. The tool cannot trust these
// bytes (a hostile model may have taken the child over), so the reader checks every count, index
// and length against the bytes received before it allocates or follows anything: whatever the
// bytes, the answer is a scene or one rt::InputError.
//
// The format, in the machine's own byte order (the same program writes and reads it):
//   "rtAR" u32 version
//   u32 meshes,    each: u32 material, u32 vertices n, u8 what it has (normals 1, UVs 2,
//                  colours 4), f32 positions[3n], normals[3n], UVs[2n], colours[4n] (as present),
//                  u32 faces, each: u32 corners k, u32 vertex[k]
//   u32 materials, each: u32 entries, each: u8 key (kMaterialKeys in the .cpp), then its value:
//                  u8 count 1-4 and f32[count] (numbers, colours), a name (strings) or i32 (a wrap mode)
//   u32 cameras,   each: name, f32 position[3], up[3], lookAt[3], horizontal fov, orthographic width
//   u32 lights,    each: name, u32 type, f32 position[3], direction[3], colour[3],
//                  attenuation constant, linear, quadratic, inner cone, outer cone
//   the node tree, depth first: name, f32 transform[16] (row major), u32 meshes, u32 mesh[...],
//                  u32 children, then each child
// A name is u32 length (below 1024, aiString's limit) and its bytes. Nothing may follow the tree.
//
// What is kept: the meshes' positions, normals, first UVs and first colours and their faces (not
// their names: Assimp's assbin dump, which this format replaced, lost them, and the models
// rt-convert writes are named after the mesh's index as they were); the
// material keys the importers ask for, as Assimp answers them; cameras, lights and nodes as
// import/assimp_import.cpp and import/model_file.cpp read them. Tangents, bones, animations,
// embedded textures and metadata are not read by rt, so they are not sent.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include <assimp/scene.h>

namespace rt {

// Deeper node trees are refused: the reader, aiNode's destructor and the importers recurse.
constexpr std::size_t kMaxReplyNodeDepth = 1024;

// The reply for `scene` (in the child). Throws rt::InputError when the scene cannot be
// written (a node tree deeper than kMaxReplyNodeDepth).
std::string writeAssimpReply(const aiScene& scene, const std::string& path);

// The scene in `reply` (in the tool): never null, its indices in range (node meshes, face
// corners, mesh materials). Throws rt::InputError "path: byte N: the reply of Assimp's
// process ...: what is wrong" on anything else.
std::unique_ptr<aiScene> readAssimpReply(const std::string& reply, const std::string& path);

}  // namespace rt
