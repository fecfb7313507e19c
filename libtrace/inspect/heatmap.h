// The heat map of rt-inspect: the scene from its camera, each pixel coloured by the work
// of its rays (traversal steps plus intersection tests), with a colour bar, its
// scale and a caption underneath. Where a tree is weak -- leaves with many primitives,
// long walks through empty space -- shows up bright.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/names.h"
#include "core/rgb_image.h"

namespace rt {

enum class HeatScale {
    Linear,  // colour proportional to the work
    Log,     // colour proportional to log(1 + work): for scenes where a few pixels cost 100x the rest
};
inline constexpr NamedValues<HeatScale, 2> kHeatScaleNames{{{"linear", HeatScale::Linear}, {"log", HeatScale::Log}}};

struct HeatmapOptions {
    HeatScale scale = HeatScale::Linear;
    std::optional<float> maximum;  // the value at the top of the bar; default: the largest cost
    std::string caption;           // drawn under the bar, left
};

// Where `value` lies on the colour bar, 0-1 (clamped).
float heatPosition(float value, float maximum, HeatScale scale);
// Round values to label the bar with, from 0 up to at most `maximum`.
std::vector<float> heatTicks(float maximum, HeatScale scale);
// The value at the top of the bar for these costs: options.maximum or the largest cost, at least 1.
float heatMaximum(const std::vector<float>& cost, const HeatmapOptions& options);

// `cost` holds width x height values, row-major, row 0 at the top (see pixelWork).
// The result is `width` wide and taller than `height` by the colour bar's strip.
RgbImage renderHeatmap(const std::vector<float>& cost, int width, int height, const HeatmapOptions& options);

}  // namespace rt
