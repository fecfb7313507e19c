// Loads a scene in the thesis's XML format (thesis 3.4.2; docs/scene-format.md).
#pragma once

#include <string>

#include "io/parameters.h"
#include "scene/scene.h"

namespace rt {

// Reads the scene file at `path` ("-" reads standard input; relative model paths then
// resolve against the current folder). Throws rt::InputError naming file and line.
// The returned scene is flattened: scene.primitives holds the world-space geometry.
// <model> files, RAW and 3ds, are read by io/model_file.h's readModelFile.
// `parameters` fill $NAME, ${NAME} and ${NAME:-default} in attribute values (io/parameters.h).
Scene loadSceneXml(const std::string& path, const SceneParameters& parameters = {});

// The same from XML text; `name` is used in messages, `baseDir` resolves model paths.
Scene loadSceneXmlFromString(const std::string& xml, const std::string& name, const std::string& baseDir,
                             const SceneParameters& parameters = {});

}  // namespace rt
