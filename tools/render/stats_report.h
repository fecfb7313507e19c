// rt-render's statistics (thesis appendix B): the thesis's one line for scripts, JSON
// with every counter, and a short summary for people.
#pragma once

#include <string>

#include "accel/accelerator.h"
#include "render/render_settings.h"
#include "render/render_stats.h"

namespace rt::render_tool {

// "preprocessing render objects lights nodes tests_per_ray", e.g. "0.09 3.51 7383 3 12423 10.05".
std::string thesisStatsLine(const RenderStats& stats);

// One JSON object with the scene, settings, accelerator and every counter.
std::string statsJson(const std::string& scene, const RenderSettings& settings, const AccelStats& accel,
                      const RenderStats& stats);

// One warning line for standard error if some samples came out NaN or infinite (written as
// black), else nothing.
std::string nonFiniteWarning(const RenderStats& stats);

// Two or three lines for standard error.
std::string statsSummary(const RenderSettings& settings, const AccelStats& accel, const RenderStats& stats,
                         bool rendered);

}  // namespace rt::render_tool
