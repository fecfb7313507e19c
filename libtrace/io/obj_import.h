// Wavefront OBJ with its .mtl files, through tinyobjloader's streaming (callback) API.
//
// Assimp reads OBJ too, but keeps every face as a heap object: converting the 2.4 MB Stanford
// bunny peaked 35 MB above start-up for 2.5 MB written. Streamed, only the vertex positions and
// each face's corner indices are held until the models are built (docs/conversion.md).
#pragma once

#include <string>

#include "io/import.h"

namespace rt {

// One Model per (object, group, material) run of faces, each placed once under
// rootTransform(options), in the order the file first uses them. Polygons are triangulated as
// Assimp does (n - 2 triangles each, concave ones ear-clipped); faces of one or two corners
// are points and lines, skipped and counted. Materials: Kd, Ks, Ns and illum of the .mtl files
// (docs/conversion.md); faces without a known material get a default one. Normals and texture
// coordinates are not used. Throws rt::InputError with file:line for a coordinate that is
// not a finite number, a face index of 0 or out of range, or a line longer than 1 MiB.
ImportResult importObj(const std::string& path, const ImportOptions& options);

}  // namespace rt
