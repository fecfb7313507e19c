#include "inspect/tree_dump.h"

#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "core/json_writer.h"

namespace rt {

namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

std::string axisName(int axis) { return axis >= 0 && axis < 3 ? kAxisNames[axis] : "?"; }

std::string nodeLabel(const TreeNodeInfo& node, bool cutOff) {
    std::ostringstream label;
    label << '#' << node.id;
    if (node.leaf) {
        label << "\\n" << node.primitives << (node.primitives == 1 ? " primitive" : " primitives");
        return label.str();
    }
    if (node.plane) label << "\\n" << axisName(node.plane->axis) << " = " << node.plane->position;
    if (cutOff) label << "\\n(cut off)";
    return label.str();
}

void writeVec3(JsonWriter& json, const Vec3& v) {
    json.beginArray();
    for (int a = 0; a < 3; ++a) json.value(double(v[a]));
    json.endArray();
}

}  // namespace

void writeTreeDot(std::ostream& out, const Accelerator& accel, const TreeCut& cut) {
    out.precision(std::numeric_limits<float>::max_digits10);
    out << "digraph " << jsonQuoted(accel.stats().name + " tree") << " {\n";
    out << "  node [shape=box, fontname=\"monospace\"];\n";
    std::vector<std::uint32_t> ancestors;  // ancestors[d] = the last node seen at depth d
    accel.forEachNode([&](const TreeNodeInfo& node) {
        if (!cut.keeps(node)) return;
        const bool cutOff = !node.leaf && cut.isCutLeaf(node);
        out << "  n" << node.id << " [label=\"" << nodeLabel(node, cutOff) << '"';
        if (node.leaf && node.primitives == 0) out << ", style=dashed";
        if (cutOff) out << ", style=dotted";
        out << "];\n";
        ancestors.resize(node.depth + 1);
        ancestors[node.depth] = node.id;
        if (node.depth > 0) out << "  n" << ancestors[node.depth - 1] << " -> n" << node.id << ";\n";
    });
    out << "}\n";
}

void writeTreeJson(std::ostream& out, const Accelerator& accel, const TreeCut& cut) {
    JsonWriter json(out);
    json.beginDocument();
    json.member("structure", accel.stats().name);
    if (cut.maxDepth) json.member("cutDepth", *cut.maxDepth);
    json.key("root");
    // Pre-order with depths: a node at depth d closes every open node at depth >= d.
    std::vector<std::uint32_t> open;
    bool anyNode = false;
    const auto closeTo = [&](std::uint32_t depth) {
        while (!open.empty() && open.back() >= depth) {
            json.endArray();
            json.endObject();
            open.pop_back();
        }
    };
    accel.forEachNode([&](const TreeNodeInfo& node) {
        if (!cut.keeps(node)) return;
        anyNode = true;
        closeTo(node.depth);
        json.beginObject();
        json.member("id", node.id);
        json.member("depth", node.depth);
        json.key("bounds");
        json.beginObject();
        json.key("lo");
        writeVec3(json, node.bounds.lo);
        json.key("hi");
        writeVec3(json, node.bounds.hi);
        json.endObject();
        if (node.leaf) {
            json.member("leaf", true);
            json.member("primitives", node.primitives);
            json.endObject();
            return;
        }
        if (node.plane) {
            json.member("axis", axisName(node.plane->axis));
            json.member("split", double(node.plane->position));
        }
        if (cut.isCutLeaf(node)) {
            json.member("cutOff", true);
            json.endObject();
            return;
        }
        json.key("children");
        json.beginArray();
        open.push_back(node.depth);
    });
    closeTo(0);
    if (!anyNode) json.null();  // a structure without nodes
    json.endObject();
}

}  // namespace rt
