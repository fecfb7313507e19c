// The wide bounding volume hierarchy (issue 37), beside the thesis's BSP and KD trees: eight
// children per node, built top-down by the binned surface area heuristic (Wald 2007), its leaves
// laid out as the trees' are (accel/leaf_store.h). docs/trees.md describes it.
#pragma once

#include <memory>

#include "accel/accelerator.h"
#include "accel/settings.h"

namespace rt {

// The primitives must outlive the BVH. The build runs on all OpenMP threads; the BVH does not
// depend on their number. Its leaves' triangles are tested with `triangles`.
std::unique_ptr<Accelerator> buildBvh(const Primitives& prims, const BvhSettings& settings,
                                      TriangleTest triangles = TriangleTest::MollerTrumbore);

}  // namespace rt
