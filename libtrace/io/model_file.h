// The formats of a scene's <model> file (thesis 3.4.3), and the one reader of them: RAW
// (appendix D, io/raw_model.h), the scene format's own, and 3ds through Assimp.
#pragma once

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
// caller): RAW through io/raw_model.h; a 3ds file through Assimp, every triangle of every
// mesh with the node transforms baked into model space. Triangles are kept as they are (the
// scene's flatten drops and counts the degenerate ones, as for RAW models). Throws
// rt::InputError naming the file, with Assimp's message for a 3ds file it rejects.
Model readModelFile(const std::string& path, Model::Format format);

}  // namespace rt
