#include "inspection.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "accel/build.h"
#include "core/error.h"
#include "image/heatmap_png.h"
#include "image/image_output.h"
#include "inspect/heatmap.h"
#include "inspect/leaf_boxes_obj.h"
#include "inspect/tree_dump.h"
#include "inspect/tree_report.h"
#include "io/load_scene.h"
#include "os/atomic_file.h"
#include "render/memory_estimate.h"
#include "tool.h"
#include "version.h"

namespace rt::tool::inspect {

namespace {

struct InspectedTree {
    std::unique_ptr<Accelerator> accel;
    TreeReport report;
};

// With several trees each gets its own file: "heat.png" becomes "heat-kd.png".
std::string pathFor(const std::string& path, const std::string& treeName, bool severalTrees) {
    if (!severalTrees) return path;
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + "-" + treeName + p.extension().string())).string();
}

void checkOptions(const InspectOptions& o) {
    const bool several = o.trees.size() > 1;
    if (several && (o.dumpPath == "-" && o.dumpFormat))
        throw InputError("--dump with several trees needs a file (-f FILE); each tree gets its own");
    if (several && o.leavesPath == "-") throw InputError("--dump-leaves - (standard output) needs a single tree");
    if (o.heatmapPath == "-") throw InputError("--heatmap needs a file name; a PNG is not written to standard output");
    // As rt-render, which refuses an extension it does not write rather than mislabel a file.
    if (!o.heatmapPath.empty() && imageFormatFromPath(o.heatmapPath) != ImageFormat::Png)
        throw InputError("--heatmap " + o.heatmapPath + ": a heat map is a PNG; give the file the extension .png");
    validate(o.picture);  // bounds the pixels, so the heat map cannot ask for more memory than a render
}

// A dump larger than this is worth a note: a tree dumps as about 1.2 KB of JSON a node, ten times
// a scene file of spheres and more (a 16.5 MB glTF's KD tree: 372 MB), which nobody expects.
constexpr std::streamoff kLargeDumpBytes = 10'000'000;

// An output that cannot be written is bad usage, found before the scene is read, as in rt-render.
void prepareOutputs(const InspectOptions& o) {
    const bool several = o.trees.size() > 1;
    for (const AccelKind kind : o.trees) {
        const std::string name = accelKindName(kind);
        if (!o.leavesPath.empty()) prepareOutputFile(pathFor(o.leavesPath, name, several));
        if (o.dumpFormat) prepareOutputFile(pathFor(o.dumpPath, name, several));
        if (!o.heatmapPath.empty()) prepareOutputFile(pathFor(o.heatmapPath, name, several));
    }
}

// Whether something other than the report goes to standard output.
bool dumpsToStdout(const InspectOptions& o) { return o.leavesPath == "-" || (o.dumpFormat && o.dumpPath == "-"); }

void writeDumps(const InspectOptions& o, const InspectedTree& tree) {
    const std::string name = accelKindName(tree.report.settings.kind);
    const bool several = o.trees.size() > 1;
    if (!o.leavesPath.empty()) {
        writeFileAtomically(pathFor(o.leavesPath, name, several),
                            [&](std::ostream& out) { writeLeafBoxesObj(out, *tree.accel, o.cut); });
    }
    if (o.dumpFormat) {
        TreeCut cut = o.cut;
        cut.nonEmptyOnly = false;  // the structure dump shows every node
        const std::string path = pathFor(o.dumpPath, name, several);
        std::streamoff bytes = -1;  // unknown on standard output
        writeFileAtomically(path, [&](std::ostream& out) {
            if (*o.dumpFormat == TreeDumpFormat::Dot)
                writeTreeDot(out, *tree.accel, cut);
            else
                writeTreeJson(out, *tree.accel, cut);
            bytes = out.tellp();
        });
        if (!o.quiet && bytes > kLargeDumpBytes)
            std::cerr << "rt-inspect: note: " << path << " is " << bytes / 1'000'000
                      << " MB: the dump holds every node of the tree (--max-depth N writes the top N levels)\n";
    }
}

// One heat map per tree; with several trees they share one scale so that they compare.
void writeHeatmaps(const InspectOptions& o, const Scene& scene, const std::vector<InspectedTree>& trees) {
    const int w = o.picture.width, h = o.picture.height;
    std::vector<std::vector<float>> costs;
    HeatmapOptions shared = o.heatmap;
    float maximum = 1;
    for (const InspectedTree& t : trees) {
        costs.push_back(pixelWork(scene, *t.accel, o.picture, o.heatmapRays));
        maximum = std::max(maximum, heatMaximum(costs.back(), o.heatmap));
    }
    if (!shared.maximum) shared.maximum = maximum;
    for (std::size_t i = 0; i < trees.size(); ++i) {
        const TreeReport& report = trees[i].report;
        shared.caption = report.stats.name + (o.heatmapRays == PixelRays::All
                                                  ? ": steps + tests per pixel, all rays"
                                                  : ": steps + tests per pixel, camera rays");  // drawn in capitals
        const std::string path = pathFor(o.heatmapPath, accelKindName(report.settings.kind), trees.size() > 1);
        writeHeatmapPng(path, renderHeatmap(costs[i], w, h, shared), std::string("rt-inspect ") + kVersion);
    }
}

void printReport(const InspectOptions& o, const SceneSummary& summary, const std::vector<InspectedTree>& trees) {
    std::vector<TreeReport> reports;
    for (const InspectedTree& t : trees) reports.push_back(t.report);
    if (o.json) {
        writeReportJson(std::cout, summary, o.rays ? std::optional(o.picture) : std::nullopt, reports);
        return;
    }
    std::cout << "scene " << summary.file << ": ";
    for (const KindCount& k : summary.primitives) std::cout << k.count << ' ' << k.name << ", ";
    std::cout << summary.lights << " lights\n";
    std::cout << "bounds " << describeBounds(summary.bounds) << "\n";
    if (o.rays) {
        const RenderSettings& p = o.picture;
        std::cout << "rays: " << p.width << "x" << p.height << ", " << p.pixelSamples << " per pixel, shadows "
                  << (p.softShadows ? "soft"
                      : p.shadows   ? "on"
                                    : "off")
                  << ", reflection depth " << p.reflectionDepth << (p.glossyReflections ? " (glossy)" : "");
        if (p.softShadows || p.glossyReflections) std::cout << ", " << p.distributedSamples << " rays per bundle";
        std::cout << "\n";
    }
    std::cout << '\n';
    printTreeTable(std::cout, reports);
    for (const TreeReport& r : reports) {
        if (!r.depths) continue;
        std::cout << "\ndepth histogram: " << r.stats.name << '\n';
        printDepthHistogram(std::cout, *r.depths);
    }
    const auto find = [&](AccelKind kind) -> const TreeReport* {
        for (const TreeReport& r : reports)
            if (r.settings.kind == kind) return &r;
        return nullptr;
    };
    const TreeReport* bsp = find(AccelKind::Bsp);
    const TreeReport* kd = find(AccelKind::Kd);
    if (o.rays && bsp && kd) {
        std::cout << '\n';
        printThesisTable43(std::cout, std::filesystem::path(summary.file).stem().string(), *bsp, *kd);
    }
}

}  // namespace

int runInspection(const InspectOptions& o) {
    checkOptions(o);
    prepareOutputs(o);
    MemoryEstimate memory;
    if (!o.heatmapPath.empty()) memory.image = heatmapMemory(o.picture.width, o.picture.height, o.trees.size());
    checkMemoryLimit(memory, o.maxMemoryGb ? std::uint64_t(*o.maxMemoryGb * 1e9) : defaultMemoryLimit(),
                     "make the heat map smaller (-x, -y)");  // before the scene is read
    Scene scene = loadScene(o.scenePath);
    scene.dropDescription();
    if (!o.quiet)
        for (const std::string& w : scene.warnings) std::cerr << "rt-inspect: warning: " << oneLine(w) << '\n';
    const SceneSummary summary = summarizeScene(o.scenePath, scene);

    std::vector<InspectedTree> trees;
    for (const AccelKind kind : o.trees) {
        InspectedTree t;
        t.report.settings = o.accel;
        t.report.settings.kind = kind;
        t.accel = buildAccelerator(scene.primitives, t.report.settings);
        t.report.stats = t.accel->stats();
        t.report.scenePrimitives = scene.primitives.size();
        if (o.rays) t.report.rays = traceRayStatistics(scene, *t.accel, o.picture);
        if (o.depthHistogram) t.report.depths = depthHistogram(*t.accel);
        writeDumps(o, t);
        trees.push_back(std::move(t));
    }
    if (!o.heatmapPath.empty()) writeHeatmaps(o, scene, trees);
    if (!dumpsToStdout(o)) printReport(o, summary, trees);
    return kExitOk;
}

}  // namespace rt::tool::inspect
