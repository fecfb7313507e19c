// Assimp in a child process (core/contained.h): some broken PLY, STL and 3DS files make it
// abort, crash, hang or ask for tens of gigabytes (docs/robustness.md), so every read runs
// apart, and the scene comes back in Assimp's own binary dump format (assbin), which the
// tool's importer reads back. Both Assimp paths use it: importAssimp and a scene's 3ds models.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <assimp/Importer.hpp>

struct aiScene;

namespace rt {

// Runs `read` in a child process, with limits that grow with the input's size
// (`inputBytes`): `read` reads the file with the Importer it is given and returns the scene,
// or throws rt::InputError. The scene is then read into `importer`, which owns it; never null.
// Throws rt::InputError naming `path` for whatever went wrong in the child.
const aiScene* readContained(Assimp::Importer& importer, const std::string& path, std::uint64_t inputBytes,
                             const std::function<const aiScene*(Assimp::Importer&)>& read);

// The tool's side of the reply: the child's assbin bytes read into `importer` by Assimp's assbin
// reader. Throws std::runtime_error naming `path` when they do not read back (the child's fault,
// not the input's). Apart from readContained for the fuzz target fuzz/assimp_reply_fuzz.cpp.
const aiScene* readReply(Assimp::Importer& importer, const std::string& path, const std::string& reply);

}  // namespace rt
