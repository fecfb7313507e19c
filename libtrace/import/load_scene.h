// The one entry point the tools use to read a scene: rt's XML scene format, or any model
// file the importers read, converted in memory.
#pragma once

#include <string>

#include "import/import.h"

namespace rt {

// "-" and files ending in .xml are read by loadSceneXml (thesis 3.4.2); anything else is
// imported with `options` (glTF, OBJ, 3DS, ...), its notes becoming the scene's warnings.
// The returned scene is flattened. Throws rt::InputError for bad input.
Scene loadScene(const std::string& path, const ImportOptions& options = {});

}  // namespace rt
