// The KD tree of thesis 2.5: planes anywhere, placed by the surface area heuristic
// (2.5.1) over the primitives' bounds clipped to each voxel ("perfect splits"), with the
// empty-space bonus and the O(N log N) build of Wald and Havran 2006 (thesis [12]).
#pragma once

#include <memory>

#include "accel/accelerator.h"
#include "accel/settings.h"

namespace rt {

// The depth limit when KdSettings::maxDepth is unset: 8 + 1.3 log2(N) (pbrt, Havran).
int defaultKdMaxDepth(std::size_t primitives);

// The depth limit a KD tree over `primitives` is built with: settings.maxDepth, or the
// default, within 0 and the traversal's stack depth (what rt-inspect reports).
int kdMaxDepth(const KdSettings& settings, std::size_t primitives);

// The primitives must outlive the tree. The build runs on all OpenMP threads; the tree
// does not depend on their number.
// Its leaves' triangles are tested with `triangles` (accel/settings.h).
std::unique_ptr<Accelerator> buildKdTree(const Primitives& prims, const KdSettings& settings,
                                         TriangleTest triangles = TriangleTest::MollerTrumbore);

}  // namespace rt
