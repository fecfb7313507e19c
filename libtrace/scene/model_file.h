// The formats of a scene's <model> file (thesis 3.4.3) and how the scene loader reads one.
// RAW (appendix D, scene/raw_model.h) is the scene format's own; a 3ds file needs Assimp,
// which only the import layer links (import/model_file.h), so the loader takes the reader.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "scene/scene.h"

namespace rt {

// "raw" or "3ds" (case-insensitive); nothing for other names.
std::optional<Model::Format> modelFormatFromName(const std::string& name);
// The format a file name's extension suggests (".raw", ".3ds"), if any.
std::optional<Model::Format> modelFormatFromExtension(const std::string& path);
const char* modelFormatName(Model::Format format);

// Reads the geometry of the model file at `path` into a Model (name and file left to the
// caller), as it is: degenerate triangles are dropped and counted later, once, by
// Scene::flatten. Throws rt::InputError naming the file.
using ModelFileReader = std::function<Model(const std::string& path, Model::Format format)>;

// The scene layer's reader: RAW files; a 3ds model is an InputError saying that it is read
// through the import layer (rt::loadScene, which passes import/model_file.h's readModelFile).
Model readRawModelFileOnly(const std::string& path, Model::Format format);

}  // namespace rt
