// rt-render's statistics (thesis appendix B): the thesis's one line for scripts, JSON
// with every counter, and a short summary for people.
#pragma once

#include <ostream>
#include <string>

#include "accel/accelerator.h"
#include "inspect/tree_report.h"
#include "render/render_settings.h"
#include "render/render_stats.h"

namespace rt::tool::render {

// "preprocessing render objects lights nodes tests_per_ray", e.g. "0.09 3.51 7383 3 12423 10.05".
std::string thesisStatsLine(const RenderStats& stats);

// --stats-json: the scene, the picture, the tree and every counter as one JSON document
// (docs/json.md), written with rt-inspect's pieces so that a quantity has one name in both.
void writeStatsJson(std::ostream& out, const SceneSummary& scene, const RenderSettings& settings,
                    const TreeReport& tree, const RenderStats& stats);

// One warning line for standard error if some samples came out NaN or infinite (written as
// black), else nothing.
std::string nonFiniteWarning(const RenderStats& stats);

// Two or three lines for standard error.
std::string statsSummary(const RenderSettings& settings, const AccelStats& accel, const RenderStats& stats,
                         bool rendered);

}  // namespace rt::tool::render
