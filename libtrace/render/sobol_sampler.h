// The path tracer's sample values: an Owen-scrambled Sobol sequence per pixel (Burley 2020,
// "Practical Hash-based Owen Scrambling", JCGT 9(4)). Each pair of dimensions takes the
// first two Sobol dimensions (a (0,2)-sequence, stratified in 2-D for every power-of-two
// prefix) with its own nested uniform scramble of the index and of each coordinate, seeded
// from a hash of (pixel, seed, dimension): pairs do not correlate with each other, and a
// pixel's values depend on nothing but its own coordinates and sample index, so the image has
// the same bits for any thread count or region split (as render/sampling.h's streams).
#pragma once

#include <cstdint>
#include <utility>

#include "core/random.h"
#include "core/real.h"

namespace rt {

namespace sobol_detail {

inline std::uint32_t reverseBits(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// A hash in which each bit depends only on the bits below it (Laine and Karras 2011, with
// Burley's constants): applied to bit-reversed values it permutes every binary interval within
// its parent, which is Owen's nested uniform scrambling.
inline std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

inline std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
    return reverseBits(laineKarrasPermutation(reverseBits(x), seed));
}

// Sobol dimension 0 is the van der Corput sequence (the index's bits reversed); dimension 1
// has direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1), from the primitive polynomial x + 1.
inline std::uint32_t sobolDimension1(std::uint32_t index) {
    std::uint32_t x = 0;
    for (std::uint32_t v = 0x80000000u; index != 0; index >>= 1, v ^= v >> 1)
        if (index & 1u) x ^= v;
    return x;
}

inline Real toUnit(std::uint32_t x) {
    // 24 bits, so the value is exact and below 1 in float as in double
    return Real(x >> 8) * Real(0x1p-24);
}

}  // namespace sobol_detail

class SobolSampler {
public:
    SobolSampler(std::uint32_t x, std::uint32_t y, std::uint32_t sample, std::uint32_t seed)
        : pixel_(mixBits((std::uint64_t(x) << 32 | y) ^ mixBits(std::uint64_t(seed) + kGoldenGamma))),
          sample_(sample) {}

    // The next two dimensions, in [0, 1)^2.
    std::pair<Real, Real> next2D() {
        using namespace sobol_detail;
        const std::uint64_t h = mixBits(pixel_ + std::uint64_t(dimension_++) * kGoldenGamma);
        const auto seed = [h](int k) { return std::uint32_t(mixBits(h + std::uint64_t(k)) >> 32); };
        const std::uint32_t index = nestedUniformScramble(sample_, seed(0));
        return {toUnit(nestedUniformScramble(reverseBits(index), seed(1))),
                toUnit(nestedUniformScramble(sobolDimension1(index), seed(2)))};
    }
    // The next dimension (the first of a pair, the second left unused).
    Real next1D() { return next2D().first; }

private:
    std::uint64_t pixel_;
    std::uint32_t sample_;
    std::uint32_t dimension_ = 0;
};

}  // namespace rt
