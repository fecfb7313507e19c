// The set of lanes (core/simd.h) that a traversal file is compiled for, and the region its code is
// compiled in. accel/kd_packet.cpp and accel/kd_single.cpp are compiled three times
// (libtrace/CMakeLists.txt): as they are, for SSE2 (simd_base); with RT_LEVEL_AVX2 defined, their
// functions compiled for AVX2; with RT_LEVEL_AVX512, for AVX-512. SplitTree's queries choose a copy
// at run time (accel/simd_dispatch.cpp), so the default build still runs on any x86-64.
//
// Included last, after every other header and in an include block of its own (clang-format sorts
// the lines of a block): the region it opens starts here, so the inline
// functions of the headers before it, which other files share, keep the baseline instructions
// (the linker keeps one copy of each for every caller; scripts/check-simd-isolation.sh checks the
// objects). The file closes the region at its end with RT_LEVEL_END. It defines:
//   RT_LEVEL            the SimdLevel the file is compiled for
//   RT_LEVEL_LANES      the namespace of its lanes: simd_base, simd_avx2 or simd_avx512
//   RT_LEVEL_NAMESPACE  the namespace for the file's own helpers, which must differ per level
#pragma once

#include "core/simd.h"

#if RT_LEVEL_AVX2
#if !RT_SIMD_AVX2
#error "RT_LEVEL_AVX2 needs core/simd.h's AVX2 lanes (x86-64, GCC or clang)"
#endif
#define RT_LEVEL_LANES simd_avx2
#define RT_LEVEL SimdLevel::avx2
#define RT_LEVEL_NAMESPACE simd_avx2
#define RT_LEVEL_END RT_AVX2_END
RT_AVX2_BEGIN
#elif RT_LEVEL_AVX512
#if !RT_SIMD_AVX512
#error "RT_LEVEL_AVX512 needs core/simd.h's AVX-512 lanes (x86-64, GCC or clang)"
#endif
#define RT_LEVEL_LANES simd_avx512
#define RT_LEVEL SimdLevel::avx512
#define RT_LEVEL_NAMESPACE simd_avx512
#define RT_LEVEL_END RT_AVX512_END
RT_AVX512_BEGIN
#else
#define RT_LEVEL_LANES simd_base
#define RT_LEVEL SimdLevel::sse2
#define RT_LEVEL_NAMESPACE inline simd_base  // reopened as what core/simd.h declares it
#define RT_LEVEL_END
#endif
