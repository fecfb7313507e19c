// The heat map of rt-inspect: the scene from its camera, each pixel coloured by the work
// of its rays (traversal steps plus intersection tests), with a colour bar, its
// scale and a caption underneath. Where a tree is weak -- leaves with many primitives,
// long walks through empty space -- shows up bright.
#pragma once

#include <cstddef>
#include <cstdint>
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

// A heat map pixel's memory at the peak (rt-inspect --max-memory; a 16384 x 16384 map of one
// tree took 2.1 GB, 7.8 bytes a pixel, a 4096 x 4096 one 7.0): each tree's work (a float), the
// picture and its PNG rows.
constexpr std::uint64_t kHeatmapBytesPerTreePixel = 4;
constexpr std::uint64_t kHeatmapBytesPerPixel = 4;

// What writing the heat maps of `trees` trees at width x height takes at the peak.
inline std::uint64_t heatmapMemory(int width, int height, std::size_t trees) {
    return std::uint64_t(width) * std::uint64_t(height) * (kHeatmapBytesPerPixel + kHeatmapBytesPerTreePixel * trees);
}

// `cost` holds width x height values, row-major, row 0 at the top (see pixelWork).
// The result is `width` wide and taller than `height` by the colour bar's strip.
RgbImage renderHeatmap(const std::vector<float>& cost, int width, int height, const HeatmapOptions& options);

}  // namespace rt
