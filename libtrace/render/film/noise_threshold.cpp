#include "render/film/noise_threshold.h"

#include <algorithm>
#include <cmath>

namespace rt {

int automaticMinSamples(float threshold) { return std::max(4, int(std::ceil(16.0f / std::pow(threshold, 0.3f)))); }

NoiseThreshold::NoiseThreshold(const RenderSettings& settings)
    : threshold_(settings.noiseThreshold),
      minSamples_(settings.adaptiveMinSamples > 0 || !enabled() ? settings.adaptiveMinSamples
                                                                : automaticMinSamples(threshold_)) {}

float NoiseThreshold::relativeError(const PixelEstimate& pixel) {
    return std::sqrt(pixel.luminanceVarianceOfMean()) / (std::max(pixel.luminanceMean, 0.0f) + kDarkLuminance);
}

}  // namespace rt
