// --seed: another seed gives independent noise, still the same bits for any thread count, so a
// farm can split a render by samples and average the parts.
#include <cmath>

#include "accel/naive.h"
#include "render/renderer.h"
#include "render_test_scenes.h"
#include "test_util.h"

using namespace rt;

namespace {

// Every random part on: jittered supersampling, soft shadows, glossy reflections.
RenderSettings noisy(int samples, std::uint32_t seed) {
    RenderSettings r = test::picture(24, 18);
    r.shadows = r.softShadows = r.glossyReflections = true;
    r.reflectionDepth = 2;
    r.distributedSamples = 2;
    r.pixelSamples = samples;
    r.seed = seed;
    return r;
}

std::vector<Color> pixels(const Scene& s, const Accelerator& accel, const RenderSettings& settings) {
    RenderStats stats;
    return render(s, accel, settings, stats).pixels();
}

double rmsError(const std::vector<Color>& a, const std::vector<Color>& reference) {
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const Color& x = a[i];
        const Color& y = reference[i];
        sum += double(x.r - y.r) * (x.r - y.r) + double(x.g - y.g) * (x.g - y.g) + double(x.b - y.b) * (x.b - y.b);
    }
    return std::sqrt(sum / double(3 * a.size()));
}

}  // namespace

TEST(RenderSeed, FourSeedsAtSixteenSamplesAreAsGoodAsOneRenderAtSixtyFour) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    const std::vector<Color> reference = pixels(s, accel, noisy(256, 0));
    const std::vector<Color> one64 = pixels(s, accel, noisy(64, 0));
    std::vector<Color> mean(reference.size());
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        const std::vector<Color> part = pixels(s, accel, noisy(16, seed));
        for (std::size_t i = 0; i < mean.size(); ++i) mean[i] += part[i] * 0.25f;
    }
    const double four16 = rmsError(mean, reference), single64 = rmsError(one64, reference);
    const double single16 = rmsError(pixels(s, accel, noisy(16, 1)), reference);
    EXPECT_LT(four16, 1.25 * single64) << "four seeds at -S 16 against one render at -S 64";
    // Four copies of the same noise would not beat one: the seeds' noise is independent.
    EXPECT_LT(four16, 0.7 * single16);
}

TEST(RenderSeed, TheDefaultIsFixedAndASeedKeepsTheBitsForAnyThreadCount) {
    const Scene s = test::spheresOnFloor();
    const NaiveAccelerator accel(s.primitives);
    EXPECT_EQ(pixels(s, accel, noisy(4, 0)), pixels(s, accel, noisy(4, 0)));
    RenderSettings one = noisy(4, 9), two = noisy(4, 9);
    one.threads = 1;
    two.threads = 2;
    EXPECT_EQ(pixels(s, accel, one), pixels(s, accel, two));
    EXPECT_NE(pixels(s, accel, one), pixels(s, accel, noisy(4, 0)));
}
