// Noise-adaptive sampling (rt-render --noise-threshold, Cycles' "noise threshold"): the path
// tracer stops sampling a pixel once its estimated error is below the threshold, so that the
// samples go where the noise is. The error is the relative standard error of the pixel's mean
// luminance, sqrt(Var[Y] / n) / (mean Y + kDarkLuminance), from the running statistics of its
// own samples (render/film/pixel_estimate.h); kDarkLuminance keeps nearly black pixels, whose
// relative error is undefined, from taking every sample for noise no one sees.
//
// A pixel is judged only at fixed sample counts, the multiples of kNoiseCheckInterval from
// adaptiveMinSamples on (Cycles' rounds; the pixel's Sobol samples, render/sobol_sampler.h, are
// stratified in aligned blocks of 16, which a pixel that stops at a block's end keeps whole), and
// only from its own samples, which are the same whatever thread, block or region traces it. So a pixel stops after the
// same sample whatever the thread count or region split, and the picture keeps its bits. A pixel it stopped still holds
// every sample it took, so its mean stays unbiased; the stop adds the small bias of any
// sequential test (a pixel whose early samples happen to agree stops early), which the minimum
// keeps small.
#pragma once

#include "render/film/pixel_estimate.h"
#include "render/render_settings.h"

namespace rt {

// A pixel is judged at the multiples of this count of samples (once it has adaptiveMinSamples).
inline constexpr int kNoiseCheckInterval = 16;

// Added to a pixel's mean luminance in the relative error (see the file comment).
inline constexpr float kDarkLuminance = 0.01f;

// The minimum of samples when --adaptive-min-samples is 0, as Cycles chooses it for its noise
// threshold: max(4, ceil(16 / threshold^0.3)), 32 at 0.1, 64 at 0.01. The threshold must be > 0.
int automaticMinSamples(float threshold);

class NoiseThreshold {
public:
    explicit NoiseThreshold(const RenderSettings& settings);

    bool enabled() const { return threshold_ > 0; }
    int minSamples() const { return minSamples_; }

    // True when the pixel takes no further sample: its count is one it is judged at and its error
    // is below the threshold there. Once true it stays so (the pixel's estimate no longer changes).
    // Inline, as the renderer asks twice per path, mostly with the threshold off.
    bool stopped(const PixelEstimate& pixel) const {
        if (!enabled() || pixel.samples < minSamples_) return false;
        return pixel.samples % kNoiseCheckInterval == 0 && relativeError(pixel) < threshold_;
    }

    // The relative standard error of the pixel's mean luminance (0 before two samples).
    static float relativeError(const PixelEstimate& pixel);

private:
    float threshold_;
    int minSamples_;
};

}  // namespace rt
