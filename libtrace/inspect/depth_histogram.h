// How a tree's nodes, leaves and primitive references spread over its depths: a tree
// that hits its depth limit (the BSP tree on uneven scenes, thesis 4.3) shows it at once.
#pragma once

#include <cstdint>
#include <ostream>
#include <vector>

#include "accel/accelerator.h"
#include "core/json_writer.h"

namespace rt {

struct DepthLevel {
    std::uint64_t nodes = 0;
    std::uint64_t leaves = 0;
    std::uint64_t emptyLeaves = 0;
    std::uint64_t primitiveReferences = 0;  // in the leaves at this depth
};

// One entry per depth from the root (0) to the deepest node.
std::vector<DepthLevel> depthHistogram(const Accelerator& accel);

void printDepthHistogram(std::ostream& out, const std::vector<DepthLevel>& levels);
// An array of {depth, nodes, leaves, emptyLeaves, primitiveReferences}.
void writeDepthHistogramJson(JsonWriter& json, const std::vector<DepthLevel>& levels);

}  // namespace rt
