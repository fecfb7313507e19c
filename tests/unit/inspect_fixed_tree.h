// A test double for the inspect tests: an "accelerator" whose tree is given node by node,
// so that dumps and histograms can be checked against a structure known in advance.
#pragma once

#include <vector>

#include "accel/accelerator.h"

namespace rt {

class FixedTree final : public Accelerator {
public:
    explicit FixedTree(std::vector<TreeNodeInfo> nodes) : nodes_(std::move(nodes)) {}

    // #0 inner, box [-2,2]^3, split x = 0
    //   #1 leaf, 2 primitives
    //   #2 inner, split y = 1
    //     #3 leaf, empty
    //     #4 leaf, 3 primitives
    static FixedTree sample() {
        const auto inner = [](std::uint32_t id, std::uint32_t depth, Aabb b, int axis, Real split) {
            TreeNodeInfo n;
            n.id = id, n.depth = depth, n.bounds = b, n.leaf = false, n.plane = SplitPlane{axis, split};
            return n;
        };
        const auto leaf = [](std::uint32_t id, std::uint32_t depth, Aabb b, std::uint32_t prims) {
            TreeNodeInfo n;
            n.id = id, n.depth = depth, n.bounds = b, n.primitives = prims;
            return n;
        };
        return FixedTree({inner(0, 0, {{-2, -2, -2}, {2, 2, 2}}, 0, 0), leaf(1, 1, {{-2, -2, -2}, {0, 2, 2}}, 2),
                          inner(2, 1, {{0, -2, -2}, {2, 2, 2}}, 1, 1), leaf(3, 2, {{0, -2, -2}, {2, 1, 2}}, 0),
                          leaf(4, 2, {{0, 1, -2}, {2, 2, 2}}, 3)});
    }

    const TreeNodeInfo& node(std::size_t i) const { return nodes_.at(i); }

    bool intersect(const Ray&, Real, Hit&, RayCounters&) const override { return false; }
    bool occluded(const Ray&, Real, RayCounters&) const override { return false; }
    AccelStats stats() const override {
        AccelStats s;
        s.name = "fixed";
        s.nodes = nodes_.size();
        return s;
    }
    void forEachNode(const std::function<void(const TreeNodeInfo&)>& visit) const override {
        for (const TreeNodeInfo& n : nodes_) visit(n);
    }

private:
    std::vector<TreeNodeInfo> nodes_;
};

}  // namespace rt
