// The choice of a traversal's copy at run time: the traversals of the trees (accel/kd_single.cpp,
// accel/kd_packet.cpp) and of the BVH (accel/bvh_traversal.cpp) are compiled once per level
// (accel/simd_level.h); their callers, compiled once, pick the copy for core/simd.h's simdLevel().
#pragma once

#include <type_traits>

#include "accel/settings.h"
#include "core/simd.h"

namespace rt {

// call(level) with the chosen level as a compile-time constant (std::integral_constant), so that
// it names that level's copy: call(level) runs X<decltype(level)::value>.
template <typename Call>
decltype(auto) onChosenLevel(const Call& call) {
#if RT_SIMD_AVX512
    if (simdLevel() == SimdLevel::avx512) return call(std::integral_constant<SimdLevel, SimdLevel::avx512>{});
#endif
#if RT_SIMD_AVX2
    if (simdLevel() == SimdLevel::avx2) return call(std::integral_constant<SimdLevel, SimdLevel::avx2>{});
#endif
    return call(std::integral_constant<SimdLevel, SimdLevel::sse2>{});
}

// call(level, test) with the chosen level and the triangle test `test` as compile-time constants:
// the copy of a single-ray search for both.
template <typename Call>
decltype(auto) onChosenCopy(TriangleTest test, const Call& call) {
    return onChosenLevel([&](auto level) -> decltype(auto) {
        if (test == TriangleTest::Watertight)
            return call(level, std::integral_constant<TriangleTest, TriangleTest::Watertight>{});
        return call(level, std::integral_constant<TriangleTest, TriangleTest::MollerTrumbore>{});
    });
}

}  // namespace rt
