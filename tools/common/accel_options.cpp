#include "accel_options.h"

#include "command_line.h"

namespace rt::tool {

namespace {

constexpr const char* kGroup = "Tree options";

}  // namespace

void addAccelOptions(CLI::App& app, AccelSettings& settings) {
    addTriangleTestOption(app, settings);
    BspSettings& bsp = settings.bsp;
    app.add_option("--bsp-max-depth", bsp.maxDepth, "BSP: maximum depth")
        ->check(numberIn(1, kMaxTreeDepth))
        ->capture_default_str()
        ->group(kGroup);
    app.add_option("--bsp-min-prims", bsp.minPrimitives, "BSP: a node with at most this many primitives is a leaf")
        ->check(numberIn(1, kMaxLeafPrimitives))
        ->capture_default_str()
        ->group(kGroup);
    app.add_flag("--bsp-round-robin", bsp.roundRobin, "BSP: split X, Y, Z in turn instead of the longest axis")
        ->group(kGroup);
    addKdOptions(app, settings.kd);
}

void addTriangleTestOption(CLI::App& app, AccelSettings& settings) {
    app.add_flag_callback(
           "--watertight", [&settings] { settings.triangles = TriangleTest::Watertight; },
           "Test triangles watertight (Woop, Benthin and Wald 2013): no ray slips through a shared edge or vertex")
        ->group(kGroup);
}

void addKdOptions(CLI::App& app, KdSettings& kd) {
    // Their ratio shapes the tree (and their scale --kd-min-gain's bound, an absolute cost); beyond
    // these bounds a cost is a typo, and products of it overflow.
    app.add_option("--kd-traversal-cost", kd.traversalCost, "KD: SAH cost of a traversal step")
        ->check(numberIn(1e-3, 1e3))
        ->capture_default_str()
        ->group(kGroup);
    app.add_option("--kd-intersection-cost", kd.intersectionCost, "KD: SAH cost of an intersection test")
        ->check(numberIn(1e-3, 1e3))
        ->capture_default_str()
        ->group(kGroup);
    app.add_option("--kd-empty-bonus", kd.emptyBonus, "KD: cost factor of splits cutting off empty space (1 = none)")
        ->check(numberIn(0.0, 1.0))
        ->capture_default_str()
        ->group(kGroup);
    app.add_option("--kd-max-depth", kd.maxDepth, "KD: maximum depth [default: 8 + 1.3 log2 N]")
        ->check(numberIn(1, kMaxTreeDepth))
        ->group(kGroup);
    addNamedOption(app, "--kd-split", kd.splitMethod, kKdSplitMethodNames,
                   "KD: split search: sweep (Wald-Havran), sort (the thesis's) or sample")
        ->group(kGroup);
    app.add_option("--kd-samples", kd.samples, "KD: candidate planes per axis for --kd-split sample")
        ->check(numberIn(1, kMaxKdSamples))
        ->capture_default_str()
        ->group(kGroup);
    app.add_option("--kd-min-gain", kd.minimumGain,
                   "KD: least SAH cost per ray a split must save, its saving times its area over the root's (0 = none)")
        ->check(numberIn(0.0, 1e3))
        ->capture_default_str()
        ->group(kGroup);
}

}  // namespace rt::tool
