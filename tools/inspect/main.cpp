// rt-inspect: statistics, dumps and heat maps of the KD and BSP trees (docs/rt-inspect.md).
#include <CLI/CLI.hpp>

#include "accel_options.h"
#include "command_line.h"
#include "inspection.h"
#include "picture_options.h"
#include "tool.h"

namespace {

using rt::tool::addNamedOption;

std::vector<rt::AccelKind> treesNamed(const std::string& name) {
    // "all" means the trees; the naive list is the reference, and tracing a real scene
    // through it takes hours, so it is inspected only by name.
    if (name == "all") return {rt::AccelKind::Bsp, rt::AccelKind::Kd, rt::AccelKind::Bvh};
    return {*rt::parseAccelKind(name)};
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Shows how the BSP and KD trees and the BVH of a scene look and perform.\n"
        "Examples:\n"
        "  rt-inspect scenes/demo.xml                     the KD tree's statistics and the scene's bounds\n"
        "  rt-inspect model.glb --tree all --rays -x 320 -y 240   BSP, KD and BVH: the work per ray\n"
        "  rt-inspect scene.xml --heatmap heat.png        where the camera rays' work goes\n"
        "  rt-inspect scene.xml --dump dot -f tree.dot --max-depth 6\n"
        "  rt-inspect scene.xml --json > report.json\n"};
    app.set_version_flag("-v,--version", rt::tool::versionLine("rt-inspect"));
    rt::tool::inspect::InspectOptions o;
    std::string tree = "kd";
    std::optional<std::uint32_t> maxDepth;
    std::optional<float> heatmapMax;

    app.add_option("scene", o.scenePath, rt::tool::kSceneHelp)->required();
    std::vector<std::string> treeNames = rt::namesOf(rt::kAccelKindNames);
    treeNames.push_back("all");
    app.add_option("-t,--tree", tree, "Which structure: naive, bsp, kd, bvh, or all (bsp, kd and bvh)")
        ->check(CLI::IsMember(treeNames))
        ->capture_default_str();
    app.add_flag("--json", o.json, "Print the statistics as one JSON document");
    app.add_flag("-q,--quiet", o.quiet, "Quiet: no warnings or notes on standard error (errors still are)");
    rt::tool::addThreadsOption(app, o.picture.threads);
    rt::tool::addMaxInputOption(app);
    rt::tool::addSandboxOption(app);
    rt::tool::addMaxMemoryOption(app, o.maxMemoryGb);

    app.add_flag("--rays", o.rays, "Render the picture (options as rt-render's) and report the work per ray");
    rt::tool::addPictureOptions(app, o.picture);

    const char* dumps = "Looking inside";
    app.add_flag("--depth-histogram", o.depthHistogram, "Leaves and primitive references per depth")->group(dumps);
    app.add_option("--dump-leaves", o.leavesPath, "Write the leaf boxes as a wireframe OBJ")->group(dumps);
    addNamedOption(app, "--leaves", o.cut.nonEmptyOnly, rt::kLeafChoiceNames, "Which leaf boxes: all or nonempty")
        ->group(dumps);
    app.add_option_function<std::string>(
           "--dump", [&o](const std::string& name) { o.dumpFormat = rt::parseNamed(rt::kTreeDumpFormatNames, name); },
           "Write the tree structure: dot (Graphviz) or json")
        ->check(CLI::IsMember(rt::namesOf(rt::kTreeDumpFormatNames)))
        ->group(dumps);
    app.add_option("-f,--file", o.dumpPath, "Where --dump writes, - for standard output")
        ->capture_default_str()
        ->group(dumps);
    app.add_option("--max-depth", maxDepth, "Dump the tree only down to this depth")->group(dumps);
    app.add_option("--heatmap", o.heatmapPath, "Write a PNG heat map of the camera rays' work")->group(dumps);
    addNamedOption(app, "--heatmap-rays", o.heatmapRays, rt::kPixelRaysNames,
                   "Work of each pixel's camera rays, or of all its rays (-s, -d, -D as for --rays)")
        ->group(dumps);
    addNamedOption(app, "--heatmap-scale", o.heatmap.scale, rt::kHeatScaleNames, "Colour scale: linear or log")
        ->group(dumps);
    app.add_option("--heatmap-max", heatmapMax, "Work at the top of the colour bar [default: the largest]")
        ->check(rt::tool::numberIn(1e-3f, 1e9f))
        ->group(dumps);
    rt::tool::addAccelOptions(app, o.accel);

    if (const std::optional<int> exitCode = rt::tool::parseCommandLine(app, "rt-inspect", argc, argv)) return *exitCode;
    o.trees = treesNamed(tree);
    o.cut.maxDepth = maxDepth;
    o.heatmap.maximum = heatmapMax;
    return rt::tool::run("rt-inspect", [&] { return rt::tool::inspect::runInspection(o); });
}
