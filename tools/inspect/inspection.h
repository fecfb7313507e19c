// What one run of rt-inspect does: load the scene, build the trees asked for, and write
// the statistics, dumps and heat maps the options name. The pieces live in libtrace/inspect.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "accel/settings.h"
#include "inspect/heatmap.h"
#include "inspect/ray_statistics.h"
#include "inspect/tree_cut.h"
#include "inspect/tree_dump.h"

namespace rt::tool::inspect {

struct InspectOptions {
    std::string scenePath;         // "-" reads standard input
    std::vector<AccelKind> trees;  // in the order they are reported
    AccelSettings accel;
    bool json = false;
    bool quiet = false;  // -q: no warnings on standard error
    bool rays = false;
    RenderSettings picture;  // whose rays --rays traces (on picture.threads); its size is the heat map's
    bool depthHistogram = false;
    std::string leavesPath;                    // --dump-leaves
    std::optional<TreeDumpFormat> dumpFormat;  // --dump dot|json; nullopt: no dump
    std::string dumpPath = "-";
    TreeCut cut;  // --max-depth and --leaves
    std::string heatmapPath;
    PixelRays heatmapRays = PixelRays::Camera;  // --heatmap-rays camera|all
    HeatmapOptions heatmap;
    std::optional<double> maxMemoryGb;  // --max-memory GB; default: rt::defaultMemoryLimit()
};

// Returns the exit code. Throws rt::InputError for bad input, other exceptions for failures.
int runInspection(const InspectOptions& options);

}  // namespace rt::tool::inspect
