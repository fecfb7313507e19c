// rt-render's statistics (thesis appendix B): the thesis's one line for scripts, JSON
// with every counter, and a short summary for people.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "accel/accelerator.h"
#include "command_line.h"
#include "inspect/tree_report.h"
#include "render/render_settings.h"
#include "render/render_stats.h"
#include "render/renderer.h"

namespace rt::tool::render {

// "preprocessing render objects lights nodes tests_per_ray", e.g. "0.09 3.51 7383 3 12423 10.05".
std::string thesisStatsLine(const RenderStats& stats);

// How a record's run was started, so that it can be repeated: rt's version, the command line,
// every option's value (given or default), and which frame of a turntable the record is for.
struct RunRecord {
    std::vector<std::string> arguments;
    OptionValues options;
    std::optional<int> frame;  // --orbit's frame; none for a single picture
};

// --stats-json: the run, the scene, the picture, the tree and every counter as one JSON document
// (docs/json.md), written with rt-inspect's pieces so that a quantity has one name in both.
// With -p, `estimate` is the predicted render (its "estimate" member; null without).
void writeStatsJson(std::ostream& out, const RunRecord& run, const SceneSummary& scene, const RenderSettings& settings,
                    const TreeReport& tree, const RenderStats& stats,
                    const std::optional<RenderEstimate>& estimate = std::nullopt);

// One warning line for standard error if some samples came out NaN or infinite (written as
// black), else nothing.
std::string nonFiniteWarning(const RenderStats& stats);

// One warning line if writing `path` held `clipped` values to a half-float EXR's range, else nothing.
std::string halfClipWarning(const std::string& path, std::uint64_t clipped);

// Why a render that --time-limit cut short wrote nothing (RenderStats::samplesPerPixel 0).
std::string timeLimitMessage(const RenderSettings& settings);

// One line for standard error when --time-limit stopped the path tracer's passes, else nothing.
std::string timeLimitNote(const RenderSettings& settings, const RenderStats& stats);

// One line for standard error when `signal` (rt::workEndRequested: SIGUSR1, or SIGINT or SIGTERM
// with --on-interrupt write) ended the path tracer's passes early, else nothing.
std::string endRequestNote(int signal, const RenderSettings& settings, const RenderStats& stats);

// -p's prediction of the render (rt::estimateRender), one line for standard error.
std::string estimateSummary(const RenderSettings& settings, const RenderEstimate& estimate);

// Two or three lines for standard error.
std::string statsSummary(const RenderSettings& settings, const AccelStats& accel, const RenderStats& stats,
                         bool rendered);

}  // namespace rt::tool::render
