#include "accel/bvh_tree.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "accel/level_dispatch.h"
#include "accel/shape_stats.h"

namespace rt {

BvhNode::BvhNode() {
    for (int axis = 0; axis < 3; ++axis) {
        std::fill(std::begin(lo[axis]), std::end(lo[axis]), kInfinity);
        std::fill(std::begin(hi[axis]), std::end(hi[axis]), -kInfinity);
    }
}

void BvhNode::add(const Aabb& box, BvhChild c) {
    for (int axis = 0; axis < 3; ++axis) {
        lo[axis][children] = box.lo[axis];
        hi[axis][children] = box.hi[axis];
    }
    child[children++] = c;
}

Aabb BvhNode::box(int slot) const {
    return {{lo[0][slot], lo[1][slot], lo[2][slot]}, {hi[0][slot], hi[1][slot], hi[2][slot]}};
}

Aabb BvhNode::bounds() const {
    Aabb all;
    for (std::uint32_t slot = 0; slot < children; ++slot) all.extend(box(int(slot)));
    return all;
}

Bvh::Bvh(const Primitives& prims, std::vector<BvhNode> nodes, LeafStore leaves, const BvhSettings& settings,
         double buildSeconds, int buildThreads)
    : prims_(prims), view_(prims.view()), nodes_(std::move(nodes)), leaves_(std::move(leaves)) {
    sceneMagnitude_ = largestMagnitude(prims.bounds());
    if (!std::isfinite(sceneMagnitude_)) sceneMagnitude_ = 0;
    stats_ = computeStats(settings);
    stats_.buildSeconds = buildSeconds;
    stats_.buildThreads = buildThreads;
}

bool Bvh::intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const {
    Hit nearest;
    nearest.t = tMax;
    if (!nodes_.empty())
        onChosenCopy(leaves_.triangleTest(), [&](auto level, auto test) {
            searchNearest<decltype(level)::value, decltype(test)::value>(ray, BvhChild::inner(0), nearest, counters);
        });
    if (!(nearest.t < tMax)) return false;
    hit = nearest;
    return true;
}

bool Bvh::occluded(const Ray& ray, Real tMax, RayCounters& counters) const {
    return !nodes_.empty() && onChosenCopy(leaves_.triangleTest(), [&](auto level, auto test) {
        return searchBlocker<decltype(level)::value, decltype(test)::value>(ray, BvhChild::inner(0), tMax, counters);
    });
}

void Bvh::intersectPacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found, RayCounters& counters) const {
    onChosenCopy(leaves_.triangleTest(), [&](auto level, auto test) {
        tracePacket<decltype(level)::value, decltype(test)::value>(rays, count, tMax, hits, found, counters);
    });
}

void Bvh::occludedPacket(const Ray* rays, int count, const Real* tMax, bool* blocked, RayCounters& counters) const {
    onChosenCopy(leaves_.triangleTest(), [&](auto level, auto test) {
        traceShadowPacket<decltype(level)::value, decltype(test)::value>(rays, count, tMax, blocked, counters);
    });
}

void Bvh::forEachNode(const std::function<void(const TreeNodeInfo&)>& visit) const {
    if (nodes_.empty()) return;
    struct Pending {
        BvhChild child;
        std::uint32_t depth;
        Aabb bounds;
    };
    // A scene of one leaf is that leaf: its root node, of one child, is the traversal's alone.
    const BvhNode& root = nodes_[0];
    const bool oneLeaf = root.children == 1 && root.child[0].isLeaf();
    std::vector<Pending> stack{{oneLeaf ? root.child[0] : BvhChild::inner(0), 0, root.bounds()}};
    std::uint32_t id = 0;
    while (!stack.empty()) {
        const Pending p = stack.back();
        stack.pop_back();
        TreeNodeInfo info;
        info.id = id++;
        info.depth = p.depth;
        info.bounds = p.bounds;
        info.leaf = p.child.isLeaf();
        if (info.leaf) {
            info.primitives = leaves_.at(p.child.index()).count();
        } else {
            const BvhNode& node = nodes_[p.child.index()];
            for (std::uint32_t slot = node.children; slot-- > 0;)  // the first slot popped first
                stack.push_back({node.child[slot], p.depth + 1, node.box(int(slot))});
        }
        visit(info);
    }
}

// The expected cost per ray by the SAH, as the trees report it: each node is entered with
// probability proportional to its box's surface area, relative to the root's.
AccelStats Bvh::computeStats(const BvhSettings& settings) const {
    AccelStats s;
    s.name = "bvh";
    s.primitives = prims_.size();
    s.memoryBytes = nodes_.size() * sizeof(BvhNode) + leaves_.bytes();
    const double rootArea = nodes_.empty() ? 0 : nodes_[0].bounds().surfaceArea();  // forEachNode's root
    addShapeStatistics(*this, rootArea, {settings.traversalCost, settings.intersectionCost}, s);
    return s;
}

}  // namespace rt
