// The one entry point the tools use to read a scene: rt's XML scene format, or any model
// file the importers read, converted in memory.
#pragma once

#include <string>

#include "io/import.h"

namespace rt {

// Files ending in .xml are read by loadSceneXml (thesis 3.4.2), their <model> files by readModelFile
// (import/model_file.h: RAW and 3ds); anything else is imported with
// `options` (glTF, OBJ, 3DS, a thesis RAW model, ...), its notes becoming the scene's warnings.
// options.camera picks the camera of an XML scene too (Scene::selectCamera), and
// options.doubleSided makes its materials two-sided.
// "-" reads standard input: a glTF 2.0 model (GLB, or JSON), else an XML scene.
// The returned scene is flattened. Throws rt::InputError for bad input.
Scene loadScene(const std::string& path, const ImportOptions& options = {});

}  // namespace rt
