#include "accel/bsp.h"

#include <algorithm>

#include "accel/tree_builder.h"
#include "core/stopwatch.h"
#include "geometry/overlap.h"

namespace rt {

namespace {

struct BspNode {
    std::vector<std::uint32_t> primitives;
    Aabb voxel;
    int depth = 0;
};

bool overlapsVoxel(const Primitives& prims, std::uint32_t id, const Aabb& voxel) {
    return prims.visit(id, [&](const auto& p) { return overlaps(p, voxel); });
}

class BspSplitter {
public:
    BspSplitter(const Primitives& prims, const BspSettings& settings)
        : prims_(prims), settings_(settings), maxDepth_(std::clamp(settings.maxDepth, 0, kMaxTreeDepth)) {}

    std::optional<Partition<BspNode>> operator()(BspNode& node) const {
        const std::size_t n = node.primitives.size();
        if (n <= std::size_t(std::max(settings_.minPrimitives, 0)) || node.depth >= maxDepth_) return std::nullopt;
        const int axis = settings_.roundRobin ? node.depth % 3 : node.voxel.longestAxis();
        const float split = float((node.voxel.lo[axis] + node.voxel.hi[axis]) / 2);
        if (!(split > node.voxel.lo[axis] && split < node.voxel.hi[axis])) return std::nullopt;  // too thin

        Partition<BspNode> parts{axis, split, {{}, node.voxel, node.depth + 1}, {{}, node.voxel, node.depth + 1}};
        parts.below.voxel.hi[axis] = split;
        parts.above.voxel.lo[axis] = split;
        for (std::uint32_t id : node.primitives) {
            // Bounds wholly on one side decide at once; only a primitive whose bounds
            // straddle the plane needs the exact tests.
            const Aabb b = prims_.bounds(id);
            const bool below =
                b.lo[axis] <= split && (b.hi[axis] <= split || overlapsVoxel(prims_, id, parts.below.voxel));
            const bool above =
                b.hi[axis] >= split && (b.lo[axis] >= split || overlapsVoxel(prims_, id, parts.above.voxel));
            // A primitive of this voxel touches one of its halves; if rounding says
            // neither, keep it in both rather than lose it.
            if (below || !above) parts.below.primitives.push_back(id);
            if (above || !below) parts.above.primitives.push_back(id);
        }
        if (!worthSplitting(node, parts)) return std::nullopt;
        return parts;
    }

private:
    // A guard the thesis does not have: the split must lower the expected number of
    // intersection tests of a ray entering the node (the SAH of thesis 2.5.1 with no
    // traversal cost). Where most primitives straddle every plane (identical triangles,
    // primitives crowded at one point) splitting on to the depth limit would double the
    // references at each level, up to 2^20-fold.
    static bool worthSplitting(const BspNode& node, const Partition<BspNode>& parts) {
        const double area = node.voxel.surfaceArea();
        if (!(area > 0)) return false;
        const double below = parts.below.voxel.surfaceArea() / area * double(parts.below.primitives.size());
        const double above = parts.above.voxel.surfaceArea() / area * double(parts.above.primitives.size());
        return below + above < double(node.primitives.size());
    }

    const Primitives& prims_;
    const BspSettings& settings_;
    int maxDepth_;
};

}  // namespace

std::unique_ptr<Accelerator> buildBspTree(const Primitives& prims, const BspSettings& settings,
                                          TriangleTest triangles) {
    const Stopwatch stopwatch;
    BspNode root{{}, roundOutToFloat(prims.bounds()), 0};
    root.primitives.resize(prims.size());
    for (std::uint32_t id = 0; id < prims.size(); ++id) root.primitives[id] = id;
    const Aabb bounds = root.voxel;
    FlatTree flat = buildFlatTree(std::move(root), BspSplitter(prims, settings));
    // The BSP has no costs of its own: it is reported with the KD tree's defaults.
    auto tree = std::make_unique<SplitTree>(prims, bounds, std::move(flat), "bsp", sahCosts(KdSettings{}), triangles);
    tree->setBuildTime(stopwatch.seconds(), buildThreads(prims.size()));
    return tree;
}

}  // namespace rt
