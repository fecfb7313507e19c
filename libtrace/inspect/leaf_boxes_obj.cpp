#include "inspect/leaf_boxes_obj.h"

#include <limits>
#include <string>

namespace rt {

namespace {

bool finiteBox(const Aabb& b) { return !b.empty() && isFinite(b.lo) && isFinite(b.hi); }

// Corner i has x from bit 0, y from bit 1, z from bit 2 (0 = lo, 1 = hi).
// The twelve edges join corners that differ in exactly one bit.
constexpr int kEdges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                               {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

void writeBox(std::ostream& out, const Aabb& b, std::size_t firstVertex) {
    for (int i = 0; i < 8; ++i) {
        out << "v " << (i & 1 ? b.hi.x : b.lo.x) << ' ' << (i & 2 ? b.hi.y : b.lo.y) << ' ' << (i & 4 ? b.hi.z : b.lo.z)
            << '\n';
    }
    for (const auto& e : kEdges) out << "l " << firstVertex + e[0] << ' ' << firstVertex + e[1] << '\n';
}

}  // namespace

std::size_t writeLeafBoxesObj(std::ostream& out, const Accelerator& accel, const TreeCut& cut) {
    out.precision(std::numeric_limits<Real>::max_digits10);
    const std::string name = accel.stats().name;
    out << "# " << name << " tree leaf voxels, written by rt-inspect\n";
    out << "o " << name << "_leaves\n";
    std::size_t boxes = 0;
    accel.forEachNode([&](const TreeNodeInfo& node) {
        if (!cut.isCutLeaf(node) || !finiteBox(node.bounds)) return;
        if (cut.nonEmptyOnly && node.leaf && node.primitives == 0) return;
        out << "# node " << node.id << " depth " << node.depth;
        if (node.leaf)
            out << " primitives " << node.primitives << '\n';
        else
            out << " (subtree cut off)\n";
        writeBox(out, node.bounds, 1 + 8 * boxes);  // OBJ vertex indices start at 1
        ++boxes;
    });
    return boxes;
}

}  // namespace rt
