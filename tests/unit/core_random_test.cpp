// SplitMix64 and Box-Muller (core/random.h): the published sequence, and the normal pair.
#include <gtest/gtest.h>

#include <cmath>

#include "core/random.h"

namespace rt {
namespace {

TEST(CoreRandom, SplitMix64GivesThePublishedSequence) {
    // Vigna's reference splitmix64.c from seed 0.
    SplitMix64 rng(0);
    EXPECT_EQ(rng.next(), 0xe220a8397b1dcdafull);
    EXPECT_EQ(rng.next(), 0x6e789e6aa1b965f4ull);
    EXPECT_EQ(rng.next(), 0x06c45d188009454full);
}

TEST(CoreRandom, UniformLiesInTheHalfOpenUnitInterval) {
    SplitMix64 rng(7);
    for (int i = 0; i < 1000; ++i) {
        const double u = rng.uniform();
        EXPECT_GE(u, 0.0);
        EXPECT_LT(u, 1.0);
    }
}

TEST(CoreRandom, BoxMullerTurnsRadiusAndAngleIntoAPair) {
    // u1 = e^-2 gives radius 2; u2 = 1/4 a quarter turn.
    const auto [a, b] = boxMuller(std::exp(-2.0), 0.25);
    EXPECT_NEAR(a, 0.0, 1e-6);
    EXPECT_NEAR(b, 2.0, 1e-6);
    EXPECT_EQ(boxMuller(1.0, 0.3).first, 0.0);  // u1 = 1: radius 0
}

}  // namespace
}  // namespace rt
