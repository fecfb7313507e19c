// One pixel's estimate from its camera samples, taken in sample-index order: the mean colour,
// the coverage (alpha) and the variance of that mean (the --aov variance layer, a noise figure).
// The mean is the plain sum times 1/n, the same float additions in the same order whether
// the samples come in one loop (Tracer::pixel) or one per pass (the progressive path tracer
// in render/renderer.cpp): K passes give the bits of -S K. The variance follows Welford's
// running update (Welford 1962; Knuth TAOCP 2, 4.2.2), stable where sum-of-squares is not; the
// luminance's own variance (not the channels' weighted sum, which leaves out their covariance) is
// what --noise-threshold stops a pixel on (render/film/noise_threshold.h).
#pragma once

#include "core/color.h"

namespace rt {

struct PixelEstimate {
    Color sum;
    Color runningMean;        // Welford's mean: exact for constant samples, where sum / n may round
    Color squaredDeviations;  // Welford's M2: the sum of squared deviations from the running mean
    float luminanceMean = 0;  // the same two of the samples' Rec.709 luminance
    float luminanceSquaredDeviations = 0;
    int samples = 0;
    int hits = 0;  // samples whose camera ray hit something

    // Adds one sample; a non-finite one counts as black and the call returns false, so that
    // the caller can record it (RenderCounters::nonFinite). A finite one beyond kMaxColorValue
    // (products of bright lights, emitters and factors) is held to it, so that the sums stay finite.
    // Without `withVariance` the variance's running sums are left alone (and the variances mean
    // nothing): the mean and coverage keep their bits at half the cost, for a caller that never
    // asks for a variance (the path tracer's passes without --aov or --noise-threshold).
    bool add(const Color& sample, bool hit, bool withVariance = true) {
        const bool finite = isFinite(sample);
        const Color x = finite ? clampedToMaxColorValue(sample) : Color{};
        const Color before = runningMean;
        sum += x;
        ++samples;
        hits += hit;
        if (!withVariance) return finite;
        const Color delta = x + before * -1.0f;
        runningMean += delta * (1.0f / float(samples));
        squaredDeviations += delta * (x + runningMean * -1.0f);
        const float y = luminance(x), deltaY = y - luminanceMean;
        luminanceMean += deltaY / float(samples);
        luminanceSquaredDeviations += deltaY * (y - luminanceMean);
        return finite;
    }

    // The mean of the samples (black before the first).
    Color mean() const { return samples <= 1 ? sum : sum * (1.0f / float(samples)); }
    float coverage() const { return samples ? float(hits) / float(samples) : 0.0f; }
    // The variance of the mean, per channel: the samples' unbiased variance over n. Zero with
    // fewer than two samples, where there is nothing to estimate it from.
    Color varianceOfMean() const {
        if (samples < 2) return {};
        return squaredDeviations * (1.0f / (float(samples - 1) * float(samples)));
    }
    // The same for the luminance.
    float luminanceVarianceOfMean() const {
        return samples < 2 ? 0.0f : luminanceSquaredDeviations / (float(samples - 1) * float(samples));
    }
};

}  // namespace rt
