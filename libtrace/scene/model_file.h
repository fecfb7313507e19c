// Loading the geometry of a scene's <model> (thesis 3.4.3) from its file, by format:
// RAW (appendix D, scene/raw_model.h) or 3ds through Assimp.
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
// caller). A 3ds file contributes every triangle of every mesh, with the node transforms
// baked into model space. Throws rt::InputError naming the file, with Assimp's message
// for a 3ds file it rejects.
Model loadModelFile(const std::string& path, Model::Format format);

}  // namespace rt
