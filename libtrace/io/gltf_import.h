// glTF 2.0 (.gltf with external or embedded buffers, .glb) through tinygltf.
#pragma once

#include <string>
#include <string_view>

#include "io/import.h"

namespace rt {

// The first 4 bytes of a binary glTF (GLB) file.
inline constexpr std::string_view kGlbMagic = "glTF";

// True when the file starts with the GLB magic "glTF" (a .glb under any name).
bool hasGlbMagic(const std::string& path);

// The chosen scene's node hierarchy (world = parent * local, TRS or matrix), every triangle
// primitive (strips and fans unrolled; points and lines skipped and counted), one Model per
// (mesh, primitive) however many nodes place it, materials through phongFromMetallicRoughness,
// the chosen perspective camera and the KHR_lights_punctual lights. Camera and light defaults
// are left to the caller. The scene sits under rootTransform(options). Throws rt::InputError
// for anything invalid.
ImportResult importGltf(const std::string& path, const ImportOptions& options);

// The same from a GLB or glTF JSON held in memory (standard input), named `name` in messages;
// relative URIs resolve against the working folder.
ImportResult importGltfBytes(const std::string& bytes, const std::string& name, const ImportOptions& options);

}  // namespace rt
