// Reproducible random numbers for distributed ray tracing (thesis 2.6). Every camera
// sample owns a stream seeded from a hash of (pixel x, pixel y, sample index, seed), as pbrt-v4
// seeds its samplers: a pixel's value depends on nothing but its own coordinates, so the
// image has the same bits for any thread count, block order or --region split.
#pragma once

#include <cmath>
#include <cstdint>
#include <tuple>

#include "core/random.h"
#include "core/vec3.h"

namespace rt {

class SampleRng {
public:
    // `seed` (rt-render --seed) picks another independent set of streams; seed 0 gives the
    // streams rt always used. Sample indices stay below 2^32, so (seed, sample) never collide.
    SampleRng(std::uint32_t x, std::uint32_t y, std::uint32_t sample, std::uint32_t seed = 0)
        : stream_(
              mixBits((std::uint64_t(x) << 32 | y) ^ mixBits((std::uint64_t(seed) << 32 | sample) + kGoldenGamma))) {}

    std::uint64_t next() { return stream_.next(); }

    // Uniform in [0, 1). 24 bits so that the value is exact, and below 1, in float too.
    Real uniform() { return Real(next() >> 40) * Real(0x1p-24); }

    // Two independent standard normal numbers.
    void normalPair(Real& a, Real& b) {
        const Real u1 = Real(1) - uniform();  // (0, 1]
        const Real u2 = uniform();
        std::tie(a, b) = boxMuller(u1, u2);
    }

private:
    SplitMix64 stream_;
};

// Where sample i of n lies inside a pixel, in [0, 1)^2: the pixel is divided into a grid
// of ceil(sqrt(n)) columns and the rows needed, and each sample is jittered inside its
// own cell (thesis 2.6.1: a regular grid combined with stochastic offsets). When n is no
// multiple of the columns, the last row is only partly filled.
inline void jitteredGridSample(int i, int n, SampleRng& rng, Real& sx, Real& sy) {
    const int cols = int(std::ceil(std::sqrt(Real(n))));
    const int rows = (n + cols - 1) / cols;
    sx = (Real(i % cols) + rng.uniform()) / Real(cols);
    sy = (Real(i / cols) + rng.uniform()) / Real(rows);
}

// Two unit vectors that complete n (unit) to a right-handed orthonormal basis
// (Duff et al. 2017, "Building an orthonormal basis, revisited").
inline void orthonormalBasis(const Vec3& n, Vec3& t, Vec3& b) {
    const Real sign = std::copysign(Real(1), n.z);
    const Real a = Real(-1) / (sign + n.z);
    const Real c = n.x * n.y * a;
    t = {1 + sign * n.x * n.x * a, sign * c, -sign * n.x};
    b = {c, sign + n.y * n.y * a, -n.y};
}

}  // namespace rt
