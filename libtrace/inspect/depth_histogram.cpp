#include "inspect/depth_histogram.h"

#include <string>

#include "inspect/text_table.h"

namespace rt {

std::vector<DepthLevel> depthHistogram(const Accelerator& accel) {
    std::vector<DepthLevel> levels;
    accel.forEachNode([&](const TreeNodeInfo& node) {
        if (node.depth >= levels.size()) levels.resize(node.depth + 1);
        DepthLevel& level = levels[node.depth];
        ++level.nodes;
        if (!node.leaf) return;
        ++level.leaves;
        if (node.primitives == 0) ++level.emptyLeaves;
        level.primitiveReferences += node.primitives;
    });
    return levels;
}

void printDepthHistogram(std::ostream& out, const std::vector<DepthLevel>& levels) {
    TextTable table({"depth", "nodes", "leaves", "empty leaves", "primitive refs"});
    for (std::size_t d = 0; d < levels.size(); ++d) {
        const DepthLevel& l = levels[d];
        table.addRow({std::to_string(d), std::to_string(l.nodes), std::to_string(l.leaves),
                      std::to_string(l.emptyLeaves), std::to_string(l.primitiveReferences)});
    }
    table.print(out);
}

void writeDepthHistogramJson(JsonWriter& json, const std::vector<DepthLevel>& levels) {
    json.beginArray();
    for (std::size_t d = 0; d < levels.size(); ++d) {
        const DepthLevel& l = levels[d];
        json.beginObject();
        json.member("depth", std::uint64_t(d));
        json.member("nodes", l.nodes);
        json.member("leaves", l.leaves);
        json.member("emptyLeaves", l.emptyLeaves);
        json.member("primitiveReferences", l.primitiveReferences);
        json.endObject();
    }
    json.endArray();
}

}  // namespace rt
