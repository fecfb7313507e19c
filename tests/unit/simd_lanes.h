// A fixture running each test once per set of lanes the packet traversal can use (core/simd.h):
// SSE2, and AVX2 and AVX-512 where the CPU has them (skipped, with a message, where not).
#pragma once

#include <gtest/gtest.h>

#include "core/simd.h"

namespace rt::test {

class SimdLanes : public ::testing::TestWithParam<SimdLevel> {
protected:
    void SetUp() override {
        if (!setSimdLevel(GetParam())) GTEST_SKIP() << "this CPU has no " << simdLevelName(GetParam());
    }
    void TearDown() override { setSimdLevel(before_); }

private:
    SimdLevel before_ = simdLevel();
};

// INSTANTIATE_SIMD_LANES(Suite): Suite's tests on every set of lanes, named sse2, avx2, avx512.
#define INSTANTIATE_SIMD_LANES(Suite)                         \
    INSTANTIATE_TEST_SUITE_P(                                 \
        Lanes, Suite, ::testing::ValuesIn(::rt::kSimdLevels), \
        [](const ::testing::TestParamInfo<::rt::SimdLevel>& level) { return ::rt::simdLevelName(level.param); })

}  // namespace rt::test
