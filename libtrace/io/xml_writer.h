// Saves a Scene in the thesis's XML format (docs/scene-format.md) so that loading it back
// gives the same scene: the same materials, camera, lights and background, and
// bit-identical primitives (numbers are written in their shortest round-trip form).
#pragma once

#include <string>

#include "scene/scene.h"

namespace rt {

// saveSceneXml(scene, "out/scene.xml") writes each model as a RAW file in the folder
// out/scene/ (named after the model, made safe as a file name) and then out/scene.xml,
// which refers to them relatively. saveSceneXml(scene, "-") writes the XML to standard
// output with every model inline (base64 RAW data). The save is atomic as a whole: the
// RAW files go to a new folder and the XML to a temporary file, and only then does the
// folder replace out/scene/ (old RAW files included) and the XML out/scene.xml, so a
// failure leaves the previous scene as it was. Loose objects become <sphere> and <triangle>; each instance a <model>
// inside a <matrix> (none for the identity). Material and model names are made unique
// and non-empty if they are not. Throws std::runtime_error if a file cannot be written,
// std::invalid_argument for a model holding both triangles and spheres (RAW holds one kind).
void saveSceneXml(const Scene& scene, const std::string& path);

// The folder saveSceneXml puts the models of `xmlPath` in: the path without its
// extension ("out/scene.xml" -> "out/scene"), or with ".models" added if it has none.
std::string modelFolderFor(const std::string& xmlPath);

}  // namespace rt
