// The checks the OBJ importer adds to tinyobjloader, which reads anything it cannot parse
// as 0 ("v nan nan nan" becomes the origin, "f 1 x 3" refers to vertex 0) and lets integers
// overflow. Each takes one whole line, as LineTrackingFile shows it, keyword included.
#pragma once

#include <optional>
#include <string_view>

#include "io/mesh_data.h"

namespace rt {

// The position of a "v" line: at least three numbers (x y z; a w or a vertex colour may
// follow), each a whole decimal number, finite in float. A comment ("# ...") may end the
// line. nullopt for anything else.
std::optional<Point3f> parseObjVertex(std::string_view line);

// True if every corner of an "f" line is v, v/t, v//n or v/t/n, each an integer of at most
// nine digits with an optional sign (so that it fits tinyobjloader's int), and no comment
// follows (tinyobjloader would read its words as corners).
bool isObjFace(std::string_view line);

}  // namespace rt
