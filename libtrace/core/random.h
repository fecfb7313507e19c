// Reproducible random numbers: SplitMix64 (Steele, Lea and Flood 2014), tiny and the same
// sequence on every machine, and the Box-Muller transform to normal numbers. Used by the
// renderer's per-sample streams (render/sampling.h), the generated scenes (scene/generate.h)
// and the tests' random rays.
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>

#include "core/real.h"

namespace rt {

// SplitMix64's increment: the odd integer nearest 2^64 / golden ratio.
inline constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ull;

// The SplitMix64 finaliser: a bijective 64-bit mix with full avalanche.
constexpr std::uint64_t mixBits(std::uint64_t v) {
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ull;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebull;
    v ^= v >> 31;
    return v;
}

// SplitMix64: a Weyl sequence through the finaliser.
class SplitMix64 {
public:
    explicit constexpr SplitMix64(std::uint64_t seed) : state_(seed) {}

    constexpr std::uint64_t next() { return mixBits(state_ += kGoldenGamma); }

    // Uniform in [0, 1), from the top 53 bits: every value exact in double.
    double uniform() { return double(next() >> 11) * 0x1.0p-53; }

private:
    std::uint64_t state_;
};

// Two independent standard normal numbers from u1 in (0, 1] (so that the logarithm stays
// finite) and u2 in [0, 1), by the Box-Muller transform (Box and Muller 1958, thesis [18]).
template <class T>
std::pair<T, T> boxMuller(T u1, T u2) {
    const T r = std::sqrt(T(-2) * std::log(u1));
    const T angle = 2 * kPi * u2;
    return {r * std::cos(angle), r * std::sin(angle)};
}

}  // namespace rt
