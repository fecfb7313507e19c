// The shape statistics every structure with nodes reports (thesis Table 4.3), from its nodes as
// forEachNode visits them: the trees (accel/split_tree.h) and the BVH (accel/bvh_tree.h) alike.
#pragma once

#include "accel/accelerator.h"

namespace rt {

// SAH constants used to report a structure's cost (thesis 2.5.1).
struct SahCosts {
    double traversal;
    double intersection;
};

// Fills in the nodes, leaves, empty leaves, depths, primitive references and the SAH cost
// `sum_inner C_T S/S_root + sum_leaves C_I N S/S_root` of `accel`, each node entered with
// probability its area over `rootArea` (1 when that is 0).
void addShapeStatistics(const Accelerator& accel, double rootArea, SahCosts costs, AccelStats& s);

}  // namespace rt
