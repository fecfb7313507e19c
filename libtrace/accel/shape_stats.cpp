#include "accel/shape_stats.h"

#include <algorithm>

namespace rt {

void addShapeStatistics(const Accelerator& accel, double rootArea, SahCosts costs, AccelStats& s) {
    double leafDepthSum = 0;
    std::uint64_t nonEmptyLeaves = 0;
    accel.forEachNode([&](const TreeNodeInfo& n) {
        ++s.nodes;
        s.maxDepth = std::max(s.maxDepth, n.depth);
        const double probability = rootArea > 0 ? n.bounds.surfaceArea() / rootArea : 1.0;
        if (!n.leaf) {
            s.sahCost += costs.traversal * probability;
            return;
        }
        ++s.leaves;
        leafDepthSum += n.depth;
        s.primitiveReferences += n.primitives;
        if (n.primitives == 0)
            ++s.emptyLeaves;
        else
            ++nonEmptyLeaves;
        s.sahCost += costs.intersection * n.primitives * probability;
    });
    s.averageLeafDepth = s.leaves ? leafDepthSum / double(s.leaves) : 0;
    s.averagePrimitivesPerLeaf = nonEmptyLeaves ? double(s.primitiveReferences) / double(nonEmptyLeaves) : 0;
}

}  // namespace rt
