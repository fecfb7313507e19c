// Reading a scene's <model> file (thesis 3.4.3) in every format the scene format names:
// the reader rt::loadScene gives the scene loader (scene/model_file.h ModelFileReader).
#pragma once

#include <string>

#include "scene/scene.h"

namespace rt {

// Reads the geometry of the model file at `path` into a Model (name and file left to the
// caller): RAW through scene/raw_model.h; a 3ds file through Assimp, every triangle of every
// mesh with the node transforms baked into model space. Triangles are kept as they are (the
// scene's flatten drops and counts the degenerate ones, as for RAW models). Throws
// rt::InputError naming the file, with Assimp's message for a 3ds file it rejects.
Model readModelFile(const std::string& path, Model::Format format);

}  // namespace rt
