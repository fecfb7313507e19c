// The recursion both tree builders share: split a node or make it a leaf, depth first,
// into a FlatTree in pre-order. Large subtrees are built as OpenMP tasks into their own
// FlatTrees and appended in a fixed order, so the tree is the same for any number of
// threads (the task only changes who builds a subtree, not what is built). An exception
// in any task (out of memory) abandons the build and is rethrown by buildFlatTree.
#pragma once

#include <omp.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>

#include "accel/build_chunks.h"
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

// Appends an inner node on `axis` at `split` and its children in pre-order: addBelow() then
// addAbove() append the two subtrees. The node's upper-child index is set once the lower
// subtree is in.
template <typename AddBelow, typename AddAbove>
void appendInner(FlatTree& out, int axis, float split, const AddBelow& addBelow, const AddAbove& addAbove) {
    const std::size_t self = out.nodes.size();
    out.nodes.push_back(SplitNode::leaf(0, 0));  // placeholder
    addBelow();
    out.nodes[self] = SplitNode::inner(axis, split, std::uint32_t(out.nodes.size()));
    addAbove();
}

// A subtree as the parallel build leaves it: built whole by one thread into `flat`, or, for a
// node of kTaskPrimitives references or more, its plane and its two children, each built by a
// task of its own. Laid out in pre-order (appendTo) once every task has finished.
struct SubtreePieces {
    FlatTree flat;
    int axis = 0;
    float split = 0;
    std::unique_ptr<SubtreePieces> below, above;  // set for a node split into tasks

    void appendTo(FlatTree& out) const {
        if (!below) {
            out.append(flat);
            return;
        }
        appendInner(
            out, axis, split, [&] { below->appendTo(out); }, [&] { above->appendTo(out); });
    }
};

// `split(node)` returns the partition of `node`, or nullopt for a leaf of node.primitives.
// One thread builds the whole subtree: a subtree below kTaskPrimitives, and a child never
// holds more references than its parent.
template <typename BuildNode, typename SplitFunction>
void buildSubtree(BuildNode node, FlatTree& out, const SplitFunction& split) {
    std::optional<Partition<BuildNode>> parts = split(node);
    if (!parts) {
        out.addLeaf(node.primitives);
        return;
    }
    node = BuildNode();  // the children hold what they need; free the parent before recursing
    appendInner(
        out, parts->axis, parts->split, [&] { buildSubtree(std::move(parts->below), out, split); },
        [&] { buildSubtree(std::move(parts->above), out, split); });
}

// A node of kTaskPrimitives references or more builds its lower child as a task and its upper
// one itself. Nobody waits for the task: in libgomp a thread waiting at a taskwait runs only
// the tasks its own task made, so a thread whose subtree was done sat idle while the other
// still had subtrees queued (for up to a third of a second in the tree scene's build).
// The threads wait at the end of the parallel region, where they run any task. An exception
// (out of memory) is captured in `errors` and abandons the build.
template <typename BuildNode, typename SplitFunction>
void buildPieces(BuildNode node, SubtreePieces& out, const SplitFunction& split, ParallelErrors& errors) {
    if (errors.failed()) return;  // another task failed: the tree is abandoned
    if (node.primitives.size() < kTaskPrimitives) {
        buildSubtree(std::move(node), out.flat, split);
        return;
    }
    std::optional<Partition<BuildNode>> parts = split(node);
    if (!parts) {
        out.flat.addLeaf(node.primitives);
        return;
    }
    node = BuildNode();
    out.axis = parts->axis;
    out.split = parts->split;
    out.below = std::make_unique<SubtreePieces>();
    out.above = std::make_unique<SubtreePieces>();
    // The task outlives this call: it owns its node and reaches the rest through pointers to
    // what lives until the parallel region ends.
    auto belowNode = std::make_shared<BuildNode>(std::move(parts->below));
    SubtreePieces* belowPieces = out.below.get();
    const SplitFunction* splitter = &split;
    ParallelErrors* failures = &errors;
#pragma omp task default(none) firstprivate(belowNode, belowPieces, splitter, failures)
    failures->capture([&] { buildPieces(std::move(*belowNode), *belowPieces, *splitter, *failures); });
    buildPieces(std::move(parts->above), *out.above, split, errors);
}

// The threads a build over `primitives` runs on: OpenMP's (rt-render --threads sets it for the
// whole process). A tree too small for a task is built without starting the threads: on a busy
// machine, waiting for them to be scheduled took longer than a 1,000-primitive build (tens of ms).
inline int buildThreads(std::size_t primitives) { return primitives >= kTaskPrimitives ? omp_get_max_threads() : 1; }

template <typename BuildNode, typename SplitFunction>
FlatTree buildFlatTree(BuildNode root, const SplitFunction& split) {
    SubtreePieces pieces;
    ParallelErrors errors;
    const int threads = buildThreads(root.primitives.size());
#pragma omp parallel num_threads(threads) if (threads > 1)
#pragma omp single
    errors.capture([&] { buildPieces(std::move(root), pieces, split, errors); });
    errors.rethrowIfAny();
    FlatTree tree;
    pieces.appendTo(tree);
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
