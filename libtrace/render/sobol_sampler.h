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

constexpr std::uint32_t reverseBits(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// A hash in which each bit depends only on the bits below it (Laine and Karras 2011, with
// Burley's constants): applied to bit-reversed values it permutes every binary interval within
// its parent, which is Owen's nested uniform scrambling: the scramble of x is
// reverseBits(laineKarrasPermutation(reverseBits(x), seed)). The sampler below takes the inner
// reversal from where it is cheaper (once per sample, or from the table).
inline std::uint32_t laineKarrasPermutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Sobol dimension 0 is the van der Corput sequence (the index's bits reversed); dimension 1
// has direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1), from the primitive polynomial x + 1:
// its value is the XOR of v_k over the index's set bits k. It is linear in those bits, so a table
// per byte of the index gives it in four lookups rather than a loop over 32 bits (the scrambled
// indices the sampler asks for have bits set everywhere). The tables hold the direction numbers
// bit-reversed, as the scramble takes the value: reversal is linear in the bits too, so the XOR
// of reversed numbers is the reversed XOR, and the scramble need not reverse it again.
struct ReversedSobolDimension1Table {
    std::uint32_t byByte[4][256];

    constexpr ReversedSobolDimension1Table() : byByte{} {
        std::uint32_t direction[32] = {};
        direction[0] = 0x80000000u;
        for (int k = 1; k < 32; ++k) direction[k] = direction[k - 1] ^ (direction[k - 1] >> 1);
        for (int b = 0; b < 4; ++b)
            for (std::uint32_t byte = 0; byte < 256; ++byte)
                for (int bit = 0; bit < 8; ++bit)
                    if (byte >> bit & 1u) byByte[b][byte] ^= reverseBits(direction[8 * b + bit]);
    }
};

// reverseBits(Sobol dimension 1 of `index`).
inline std::uint32_t reversedSobolDimension1(std::uint32_t index) {
    static constexpr ReversedSobolDimension1Table table;
    return table.byByte[0][index & 0xffu] ^ table.byByte[1][index >> 8 & 0xffu] ^ table.byByte[2][index >> 16 & 0xffu] ^
           table.byByte[3][index >> 24];
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
          reversedSample_(sobol_detail::reverseBits(sample)) {}

    // The next two dimensions, in [0, 1)^2.
    std::pair<Real, Real> next2D() {
        using namespace sobol_detail;
        const std::uint64_t h = nextDimension();
        const std::uint32_t index = scrambledIndex(h);
        // dimension 1 scrambled, its inner reversal taken by the table
        return {first(index, h),
                toUnit(reverseBits(laineKarrasPermutation(reversedSobolDimension1(index), seed(h, 2))))};
    }
    // The next dimension: the first of a pair, the second left unused (and not computed).
    Real next1D() {
        const std::uint64_t h = nextDimension();
        return first(scrambledIndex(h), h);
    }

private:
    // The hash of the pixel and the pair of dimensions that seeds the pair's scrambles.
    std::uint64_t nextDimension() { return mixBits(pixel_ + std::uint64_t(dimension_++) * kGoldenGamma); }
    static std::uint32_t seed(std::uint64_t h, int k) { return std::uint32_t(mixBits(h + std::uint64_t(k)) >> 32); }
    // The sample's index, shuffled for this pair (Burley's "shuffled" Sobol sequence):
    // the sample scrambled, its inner reversal made once for all pairs.
    std::uint32_t scrambledIndex(std::uint64_t h) const {
        using namespace sobol_detail;
        return reverseBits(laineKarrasPermutation(reversedSample_, seed(h, 0)));
    }
    // Dimension 0, scrambled: the scramble of reverseBits(index), whose two inner bit
    // reversals cancel.
    static Real first(std::uint32_t index, std::uint64_t h) {
        using namespace sobol_detail;
        return toUnit(reverseBits(laineKarrasPermutation(index, seed(h, 1))));
    }

    std::uint64_t pixel_;
    std::uint32_t reversedSample_;  // the sample's index, bits reversed
    std::uint32_t dimension_ = 0;
};

}  // namespace rt
