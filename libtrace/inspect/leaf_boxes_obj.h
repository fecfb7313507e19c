// The voxels of a tree's leaves as a wireframe Wavefront OBJ: eight vertices and twelve
// line elements ("l") per box, in world coordinates, so that Blender or any OBJ viewer
// shows the boxes over the scene's own geometry.
#pragma once

#include <cstddef>
#include <ostream>

#include "accel/accelerator.h"
#include "inspect/tree_cut.h"

namespace rt {

// Writes one box per leaf of the cut tree (see TreeCut); returns how many were written.
std::size_t writeLeafBoxesObj(std::ostream& out, const Accelerator& accel, const TreeCut& cut);

}  // namespace rt
