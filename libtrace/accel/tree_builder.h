// The recursion both tree builders share: split a node or make it a leaf, depth first,
// into a FlatTree in pre-order. Large subtrees are built as OpenMP tasks into their own
// FlatTrees and appended in a fixed order, so the tree is the same for any number of
// threads (the task only changes who builds a subtree, not what is built). An exception
// in any task (out of memory) abandons the build and is rethrown by buildFlatTree.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include "accel/split_tree.h"
#include "core/aabb.h"
#include "core/parallel_errors.h"

namespace rt {

// What a builder's split function returns for an inner node: the plane and the two
// children's build nodes (each with a `primitives` vector of ids).
template <typename BuildNode>
struct Partition {
    int axis;
    float split;
    BuildNode below, above;
};

// Below this many primitive references a subtree is built by the thread that reached it.
constexpr std::size_t kTaskPrimitives = 16384;

// `split(node)` returns the partition of `node`, or nullopt for a leaf of node.primitives.
// A subtree below kTaskPrimitives spawns no task (a child never holds more references than
// its parent), so exceptions there unwind to the nearest task, which captures them in `errors`.
template <typename BuildNode, typename SplitFunction>
void buildSubtree(BuildNode node, FlatTree& out, const SplitFunction& split, ParallelErrors& errors) {
    if (errors.failed()) return;  // another task failed: the tree is abandoned
    std::optional<Partition<BuildNode>> parts = split(node);
    if (!parts) {
        out.addLeaf(node.primitives);
        return;
    }
    const bool parallel = node.primitives.size() >= kTaskPrimitives;
    node = BuildNode();  // the children hold what they need; free the parent before recursing
    if (!parallel) {
        const std::size_t self = out.nodes.size();
        out.nodes.push_back(SplitNode::leaf(0, 0));  // placeholder until the above child's index is known
        buildSubtree(std::move(parts->below), out, split, errors);
        out.nodes[self] = SplitNode::inner(parts->axis, parts->split, std::uint32_t(out.nodes.size()));
        buildSubtree(std::move(parts->above), out, split, errors);
        return;
    }
    // Nothing may unwind past the taskwait while the task still uses `below` and `parts`.
    FlatTree below, above;
#pragma omp task default(shared)
    errors.capture([&] { buildSubtree(std::move(parts->below), below, split, errors); });
    errors.capture([&] { buildSubtree(std::move(parts->above), above, split, errors); });
#pragma omp taskwait
    if (errors.failed()) return;
    out.nodes.push_back(
        SplitNode::inner(parts->axis, parts->split, std::uint32_t(out.nodes.size() + 1 + below.nodes.size())));
    out.append(below);
    out.append(above);
}

// A tree too small for a task is built without starting the threads: on a busy machine,
// waiting for them to be scheduled took longer than a 1,000-primitive build (tens of ms).
template <typename BuildNode, typename SplitFunction>
FlatTree buildFlatTree(BuildNode root, const SplitFunction& split) {
    FlatTree tree;
    ParallelErrors errors;
    const bool parallel = root.primitives.size() >= kTaskPrimitives;
#pragma omp parallel if (parallel)
#pragma omp single
    errors.capture([&] { buildSubtree(std::move(root), tree, split, errors); });
    errors.rethrowIfAny();
    return tree;
}

// The root voxel: the primitives' bounds rounded outwards to float, so that every split
// plane (a float, see SplitNode) can lie exactly on a voxel face.
inline float floatBelow(Real x) {
    const float f = float(x);
    return Real(f) > x ? std::nextafter(f, -INFINITY) : f;
}
inline float floatAbove(Real x) {
    const float f = float(x);
    return Real(f) < x ? std::nextafter(f, INFINITY) : f;
}
inline Aabb roundOutToFloat(const Aabb& b) {
    return {{floatBelow(b.lo.x), floatBelow(b.lo.y), floatBelow(b.lo.z)},
            {floatAbove(b.hi.x), floatAbove(b.hi.y), floatAbove(b.hi.z)}};
}

}  // namespace rt
