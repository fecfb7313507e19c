// The BSP tree of thesis 2.4: every plane halves its voxel, on the voxel's longest axis
// (or X, Y, Z in turn). A primitive cut by the plane goes to both halves, decided by
// exact overlap tests rather than bounding boxes (thesis 2.4.1, [9], [10]).
#pragma once

#include <memory>

#include "accel/accelerator.h"
#include "accel/settings.h"

namespace rt {

// The primitives must outlive the tree. Its leaves' triangles are tested with `triangles`.
std::unique_ptr<Accelerator> buildBspTree(const Primitives& prims, const BspSettings& settings,
                                          TriangleTest triangles = TriangleTest::MollerTrumbore);

}  // namespace rt
