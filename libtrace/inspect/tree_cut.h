// Which nodes of a tree a dump shows. Cutting a tree at depth N keeps the nodes down to
// depth N; an inner node at depth N then stands for its whole subtree, so the boxes of
// a cut tree still cover everything the tree covers.
#pragma once

#include <cstdint>
#include <optional>

#include "accel/accelerator.h"
#include "core/names.h"

namespace rt {

// rt-inspect --leaves all|nonempty: the value of TreeCut::nonEmptyOnly.
inline constexpr NamedValues<bool, 2> kLeafChoiceNames{{{"all", false}, {"nonempty", true}}};

struct TreeCut {
    std::optional<std::uint32_t> maxDepth;  // nullopt: the whole tree
    bool nonEmptyOnly = false;              // leave out empty leaves (the leaf-box dump; kLeafChoiceNames)

    bool keeps(const TreeNodeInfo& node) const { return !maxDepth || node.depth <= *maxDepth; }
    // True for the nodes drawn as boxes: leaves, and inner nodes cut off at maxDepth.
    bool isCutLeaf(const TreeNodeInfo& node) const {
        return keeps(node) && (node.leaf || (maxDepth && node.depth == *maxDepth));
    }
};

}  // namespace rt
