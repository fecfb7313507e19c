// Assimp in a child process (os/contained.h): some broken PLY, STL and 3DS files make it
// abort, crash, hang or ask for tens of gigabytes (docs/robustness.md), so every read runs
// apart, and the scene comes back as a reply of rt's own (import/assimp_reply.h) that the tool
// reads with every count checked. Both Assimp paths use it: importAssimp and a scene's 3ds models.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <assimp/Importer.hpp>

struct aiScene;

namespace rt {

// Runs `read` in a child process, with limits that grow with the input's size
// (`inputBytes`): `read` reads the file with the Importer it is given and returns the scene,
// or throws rt::InputError. The scene comes back as the tool's own aiScene; never null.
// Throws rt::InputError naming `path` for whatever went wrong in the child or in its reply.
std::unique_ptr<aiScene> readContained(const std::string& path, std::uint64_t inputBytes,
                                       const std::function<const aiScene*(Assimp::Importer&)>& read);

}  // namespace rt
