// The structure of a tree, down to a chosen depth, for people (Graphviz DOT: render it with
// `dot -Tsvg`) and for scripts (nested JSON). Inner nodes show their split plane, leaves
// their primitive count; an inner node at the cut depth is marked as cut off.
#pragma once

#include <ostream>

#include "accel/accelerator.h"
#include "core/names.h"
#include "inspect/tree_cut.h"

namespace rt {

enum class TreeDumpFormat { Dot, Json };
inline constexpr NamedValues<TreeDumpFormat, 2> kTreeDumpFormatNames{
    {{"dot", TreeDumpFormat::Dot}, {"json", TreeDumpFormat::Json}}};

void writeTreeDot(std::ostream& out, const Accelerator& accel, const TreeCut& cut);

// {"version", "structure": name, "cutDepth" (with a cut), "root": {"id", "depth", "bounds":
// {"lo", "hi"}, then either "leaf": true and "primitives", or "axis", "split" and "children"
// (or "cutOff": true at the cut depth)}} (docs/json.md).
void writeTreeJson(std::ostream& out, const Accelerator& accel, const TreeCut& cut);

}  // namespace rt
