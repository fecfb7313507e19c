// Lanes of Real: the few operations the leaf tests (geometry/triangle_block.h) and the packet
// traversal (accel/kd_packet.cpp) need, in two sets.
//
// RealLanes (namespace simd_base, inline in rt): one SSE2 register (every x86-64 CPU has SSE2,
// so the default build runs anywhere): two lanes with Real = double, four with float; four in
// plain C++ elsewhere. The leaves' triangle blocks are kSimdWidth wide, this register's width,
// whatever the packets use: a leaf holds few triangles (2-3 in a KD tree), so wider blocks would
// mostly test and store empty lanes. The single-ray traversal (accel/kd_single.cpp) tests them on
// these lanes on every level: its AVX2 and AVX-512 copies are the same code compiled for those
// instruction sets (three-operand forms, more registers), not wider lanes.
//
// simd_avx2::RealLanes: one AVX2 register, four doubles or eight floats, for the packet
// traversal only. Its functions are compiled for AVX2 whatever the flags of the file
// (RT_AVX2_BEGIN/END), so the default build still runs on any x86-64; code may call them only
// where simdLevel() says the CPU has AVX2 (accel/kd_packet.cpp is compiled a second time into
// that namespace, accel/simd_level.h, and SplitTree::intersectPacket chooses at run time).
//
// simd_avx512::RealLanes: the same for AVX-512 (F, DQ, VL; RT_AVX512_BEGIN/END), kd_packet.cpp's
// third copy. With doubles one ZMM register holds the whole packet of eight rays, so each step
// is one instruction where AVX2 needs two. With floats AVX2's one YMM register already holds the
// eight, and a ZMM register would hold sixteen lanes, half of them always empty: the level keeps
// AVX2's eight-float lanes, compiled for AVX-512VL, which gives the traversal 32 vector registers
// instead of 16. RT_SIMD=sse2|avx2|avx512 in the environment, or setSimdLevel, picks a level the
// CPU has (the tests run each).
//
// Each lane of every set rounds exactly as the scalar code does (IEEE add, sub, mul, div; no
// fused multiply-add: the AVX2 functions are compiled without FMA, and as AVX-512F has fused
// instructions of its own, code on the AVX-512 lanes is compiled with -ffp-contract=off, see
// libtrace/CMakeLists.txt), so a lane's answer has the scalar test's bits: the trees, their
// packets and the naive list agree to the last bit.
#pragma once

#include <cmath>

#include "core/real.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#define RT_SIMD_SSE2 1
#endif

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define RT_SIMD_AVX2 1
// The functions defined between RT_AVX2_BEGIN and RT_AVX2_END are compiled for AVX2 (and not
// FMA), whatever the file's flags; headers included outside them keep the file's flags, so no
// inline function that other files share is ever built for AVX2 (the avx2_isolation and
// avx512_isolation tests check the objects' code). RT_AVX512_BEGIN/END the same for AVX-512: F
// (ZMM registers, k masks), DQ (the bitwise operations on doubles and the moves between k masks
// and lanes), VL (EVEX on YMM registers, and registers 16-31 for the float build's YMM lanes).
#if defined(__clang__)
#define RT_SIMD_TARGET_BEGIN(isa) \
    _Pragma(RT_SIMD_STRING(clang attribute push(__attribute__((target(isa))), apply_to = function)))
#define RT_SIMD_TARGET_END _Pragma("clang attribute pop")
#else
#define RT_SIMD_TARGET_BEGIN(isa) _Pragma("GCC push_options") _Pragma(RT_SIMD_STRING(GCC target(isa)))
#define RT_SIMD_TARGET_END _Pragma("GCC pop_options")
#endif
#define RT_SIMD_STRING(...) #__VA_ARGS__
#define RT_AVX2_BEGIN RT_SIMD_TARGET_BEGIN("avx2")
#define RT_AVX2_END RT_SIMD_TARGET_END
#define RT_SIMD_AVX512 1
#define RT_AVX512_BEGIN RT_SIMD_TARGET_BEGIN("avx512f,avx512dq,avx512vl")
#define RT_AVX512_END RT_SIMD_TARGET_END
#endif

namespace rt {

#if RT_SIMD_SSE2 && !defined(RT_REAL_FLOAT)
inline constexpr int kSimdWidth = 2;
#else
inline constexpr int kSimdWidth = 4;
#endif

inline namespace simd_base {

inline constexpr int kLanes = kSimdWidth;  // per register

#if RT_SIMD_SSE2 && !defined(RT_REAL_FLOAT)

// Two doubles; a mask is the same, all ones or all zeros per lane.
struct RealLanes {
    __m128d v;
};
inline RealLanes loadLanes(const Real* p) { return {_mm_load_pd(p)}; }
inline RealLanes broadcast(Real x) { return {_mm_set1_pd(x)}; }
inline void storeLanes(Real* p, RealLanes a) { _mm_storeu_pd(p, a.v); }
inline RealLanes operator+(RealLanes a, RealLanes b) { return {_mm_add_pd(a.v, b.v)}; }
inline RealLanes operator-(RealLanes a, RealLanes b) { return {_mm_sub_pd(a.v, b.v)}; }
inline RealLanes operator*(RealLanes a, RealLanes b) { return {_mm_mul_pd(a.v, b.v)}; }
inline RealLanes operator/(RealLanes a, RealLanes b) { return {_mm_div_pd(a.v, b.v)}; }
inline RealLanes squareRoot(RealLanes a) { return {_mm_sqrt_pd(a.v)}; }
inline RealLanes operator&(RealLanes a, RealLanes b) { return {_mm_and_pd(a.v, b.v)}; }
inline RealLanes lessThan(RealLanes a, RealLanes b) { return {_mm_cmplt_pd(a.v, b.v)}; }
// !(a < b), true where either is NaN, as the scalar `if (a < b) reject` lets NaN through.
inline RealLanes notLessThan(RealLanes a, RealLanes b) { return {_mm_cmpnlt_pd(a.v, b.v)}; }
inline RealLanes notGreaterThan(RealLanes a, RealLanes b) { return {_mm_cmpngt_pd(a.v, b.v)}; }
inline RealLanes notEqual(RealLanes a, RealLanes b) { return {_mm_cmpneq_pd(a.v, b.v)}; }
// Bit i set where lane i of the mask is set.
inline unsigned laneBits(RealLanes mask) { return unsigned(_mm_movemask_pd(mask.v)); }
// For the packet traversal (accel/kd_packet.cpp): masks combined and chosen between.
inline RealLanes operator|(RealLanes a, RealLanes b) { return {_mm_or_pd(a.v, b.v)}; }
inline RealLanes andNot(RealLanes a, RealLanes b) { return {_mm_andnot_pd(a.v, b.v)}; }  // ~a & b
inline RealLanes lessEqual(RealLanes a, RealLanes b) { return {_mm_cmple_pd(a.v, b.v)}; }
// Lane by lane: a where the mask is set, else b.
inline RealLanes select(RealLanes mask, RealLanes a, RealLanes b) {
    return {_mm_or_pd(_mm_and_pd(mask.v, a.v), _mm_andnot_pd(mask.v, b.v))};
}
// For the BVH's slab tests (accel/bvh_traversal.cpp): a < b ? a : b and a > b ? a : b, lane by
// lane, so b where either is NaN (as the instructions of every level answer).
inline RealLanes minimum(RealLanes a, RealLanes b) { return {_mm_min_pd(a.v, b.v)}; }
inline RealLanes maximum(RealLanes a, RealLanes b) { return {_mm_max_pd(a.v, b.v)}; }

#elif RT_SIMD_SSE2

struct RealLanes {
    __m128 v;
};
inline RealLanes loadLanes(const Real* p) { return {_mm_load_ps(p)}; }
inline RealLanes broadcast(Real x) { return {_mm_set1_ps(x)}; }
inline void storeLanes(Real* p, RealLanes a) { _mm_storeu_ps(p, a.v); }
inline RealLanes operator+(RealLanes a, RealLanes b) { return {_mm_add_ps(a.v, b.v)}; }
inline RealLanes operator-(RealLanes a, RealLanes b) { return {_mm_sub_ps(a.v, b.v)}; }
inline RealLanes operator*(RealLanes a, RealLanes b) { return {_mm_mul_ps(a.v, b.v)}; }
inline RealLanes operator/(RealLanes a, RealLanes b) { return {_mm_div_ps(a.v, b.v)}; }
inline RealLanes squareRoot(RealLanes a) { return {_mm_sqrt_ps(a.v)}; }
inline RealLanes operator&(RealLanes a, RealLanes b) { return {_mm_and_ps(a.v, b.v)}; }
inline RealLanes lessThan(RealLanes a, RealLanes b) { return {_mm_cmplt_ps(a.v, b.v)}; }
inline RealLanes notLessThan(RealLanes a, RealLanes b) { return {_mm_cmpnlt_ps(a.v, b.v)}; }
inline RealLanes notGreaterThan(RealLanes a, RealLanes b) { return {_mm_cmpngt_ps(a.v, b.v)}; }
inline RealLanes notEqual(RealLanes a, RealLanes b) { return {_mm_cmpneq_ps(a.v, b.v)}; }
inline unsigned laneBits(RealLanes mask) { return unsigned(_mm_movemask_ps(mask.v)); }
inline RealLanes operator|(RealLanes a, RealLanes b) { return {_mm_or_ps(a.v, b.v)}; }
inline RealLanes andNot(RealLanes a, RealLanes b) { return {_mm_andnot_ps(a.v, b.v)}; }
inline RealLanes lessEqual(RealLanes a, RealLanes b) { return {_mm_cmple_ps(a.v, b.v)}; }
inline RealLanes select(RealLanes mask, RealLanes a, RealLanes b) {
    return {_mm_or_ps(_mm_and_ps(mask.v, a.v), _mm_andnot_ps(mask.v, b.v))};
}
inline RealLanes minimum(RealLanes a, RealLanes b) { return {_mm_min_ps(a.v, b.v)}; }
inline RealLanes maximum(RealLanes a, RealLanes b) { return {_mm_max_ps(a.v, b.v)}; }

#else

// The portable path: a mask lane is 1 or 0.
struct RealLanes {
    Real v[4];
};
template <class F>
RealLanes eachLane(RealLanes a, RealLanes b, F f) {
    return {{f(a.v[0], b.v[0]), f(a.v[1], b.v[1]), f(a.v[2], b.v[2]), f(a.v[3], b.v[3])}};
}
inline RealLanes loadLanes(const Real* p) { return {{p[0], p[1], p[2], p[3]}}; }
inline RealLanes broadcast(Real x) { return {{x, x, x, x}}; }
inline void storeLanes(Real* p, RealLanes a) {
    for (int i = 0; i < 4; ++i) p[i] = a.v[i];
}
inline RealLanes operator+(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return x + y; });
}
inline RealLanes operator-(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return x - y; });
}
inline RealLanes operator*(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return x * y; });
}
inline RealLanes operator/(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return x / y; });
}
inline RealLanes squareRoot(RealLanes a) {
    return eachLane(a, a, [](Real x, Real) { return std::sqrt(x); });
}
inline RealLanes operator&(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return Real(x != 0 && y != 0); });
}
inline RealLanes lessThan(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return Real(x < y); });
}
inline RealLanes notLessThan(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return Real(!(x < y)); });
}
inline RealLanes notGreaterThan(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return Real(!(x > y)); });
}
inline RealLanes notEqual(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return Real(x != y); });
}
inline unsigned laneBits(RealLanes mask) {
    unsigned bits = 0;
    for (int i = 0; i < 4; ++i) bits |= unsigned(mask.v[i] != 0) << i;
    return bits;
}
inline RealLanes operator|(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return Real(x != 0 || y != 0); });
}
inline RealLanes andNot(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return Real(x == 0 && y != 0); });
}
inline RealLanes lessEqual(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return Real(x <= y); });
}
inline RealLanes select(RealLanes mask, RealLanes a, RealLanes b) {
    return {{mask.v[0] != 0 ? a.v[0] : b.v[0], mask.v[1] != 0 ? a.v[1] : b.v[1], mask.v[2] != 0 ? a.v[2] : b.v[2],
             mask.v[3] != 0 ? a.v[3] : b.v[3]}};
}
inline RealLanes minimum(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return x < y ? x : y; });
}
inline RealLanes maximum(RealLanes a, RealLanes b) {
    return eachLane(a, b, [](Real x, Real y) { return x > y ? x : y; });
}

#endif

}  // namespace simd_base

// Which copy of the traversals (single rays and packets) runs. Chosen once, at the first call: the
// widest the CPU has, AVX-512 then AVX2, unless the environment names another the CPU has
// (RT_SIMD=sse2|avx2|avx512); setSimdLevel changes it (tests).
enum class SimdLevel { sse2, avx2, avx512 };  // sse2: simd_base (plain C++ off x86-64)
inline constexpr SimdLevel kSimdLevels[] = {SimdLevel::sse2, SimdLevel::avx2, SimdLevel::avx512};
bool cpuHas(SimdLevel level);
SimdLevel simdLevel();
// False, changing nothing, where the CPU cannot run `level`.
bool setSimdLevel(SimdLevel level);
const char* simdLevelName(SimdLevel level);

#if RT_SIMD_AVX2

// The operations that are one intrinsic each, named OP(add) and so on for the level's register
// (_mm256_add_pd, _mm512_add_pd, ...): the AVX2 and the AVX-512 lanes define them alike.
#define RT_SIMD_ONE_INTRINSIC_OPERATIONS(OP)                                             \
    inline RealLanes loadLanes(const Real* p) { return {OP(loadu)(p)}; }                 \
    inline RealLanes broadcast(Real x) { return {OP(set1)(x)}; }                         \
    inline void storeLanes(Real* p, RealLanes a) { OP(storeu)(p, a.v); }                 \
    inline RealLanes operator+(RealLanes a, RealLanes b) { return {OP(add)(a.v, b.v)}; } \
    inline RealLanes operator-(RealLanes a, RealLanes b) { return {OP(sub)(a.v, b.v)}; } \
    inline RealLanes operator*(RealLanes a, RealLanes b) { return {OP(mul)(a.v, b.v)}; } \
    inline RealLanes operator/(RealLanes a, RealLanes b) { return {OP(div)(a.v, b.v)}; } \
    inline RealLanes operator&(RealLanes a, RealLanes b) { return {OP(and)(a.v, b.v)}; } \
    inline RealLanes operator|(RealLanes a, RealLanes b) { return {OP(or)(a.v, b.v)}; }  \
    inline RealLanes andNot(RealLanes a, RealLanes b) { return {OP(andnot)(a.v, b.v)}; } /* ~a & b */

// The SSE2 comparisons' answers, NaN included: ordered where SSE2's are (false on NaN),
// unordered where they are negated (true on NaN); quiet, as no flag is read. COMPARE(a, b,
// predicate) gives the level's mask.
#define RT_SIMD_COMPARISONS(COMPARE)                                                                     \
    inline RealLanes lessThan(RealLanes a, RealLanes b) { return COMPARE(a.v, b.v, _CMP_LT_OQ); }        \
    inline RealLanes lessEqual(RealLanes a, RealLanes b) { return COMPARE(a.v, b.v, _CMP_LE_OQ); }       \
    inline RealLanes notLessThan(RealLanes a, RealLanes b) { return COMPARE(a.v, b.v, _CMP_NLT_UQ); }    \
    inline RealLanes notGreaterThan(RealLanes a, RealLanes b) { return COMPARE(a.v, b.v, _CMP_NGT_UQ); } \
    inline RealLanes notEqual(RealLanes a, RealLanes b) { return COMPARE(a.v, b.v, _CMP_NEQ_UQ); }

namespace simd_avx2 {

RT_AVX2_BEGIN

#if defined(RT_REAL_FLOAT)
inline constexpr int kLanes = 8;
struct RealLanes {
    __m256 v;
};
#define RT_AVX2_OP(name) _mm256_##name##_ps
#else
inline constexpr int kLanes = 4;
struct RealLanes {
    __m256d v;
};
#define RT_AVX2_OP(name) _mm256_##name##_pd
#endif
#define RT_AVX2_COMPARE(a, b, predicate) \
    RealLanes { RT_AVX2_OP(cmp)(a, b, predicate) }

RT_SIMD_ONE_INTRINSIC_OPERATIONS(RT_AVX2_OP)
RT_SIMD_COMPARISONS(RT_AVX2_COMPARE)
inline unsigned laneBits(RealLanes mask) { return unsigned(RT_AVX2_OP(movemask)(mask.v)); }
inline RealLanes squareRoot(RealLanes a) { return {RT_AVX2_OP(sqrt)(a.v)}; }
inline RealLanes select(RealLanes mask, RealLanes a, RealLanes b) { return {RT_AVX2_OP(blendv)(b.v, a.v, mask.v)}; }
inline RealLanes minimum(RealLanes a, RealLanes b) { return {RT_AVX2_OP(min)(a.v, b.v)}; }
inline RealLanes maximum(RealLanes a, RealLanes b) { return {RT_AVX2_OP(max)(a.v, b.v)}; }
// The lanes of two SSE2 registers' worth, `low` in the lower half: two leaf blocks tested at once
// (accel/kd_single.cpp).
#if defined(RT_REAL_FLOAT)
inline RealLanes loadHalves(const Real* low, const Real* high) { return {_mm256_loadu2_m128(high, low)}; }
#else
inline RealLanes loadHalves(const Real* low, const Real* high) { return {_mm256_loadu2_m128d(high, low)}; }
#endif

#undef RT_AVX2_COMPARE
#undef RT_AVX2_OP

RT_AVX2_END

}  // namespace simd_avx2

namespace simd_avx512 {

RT_AVX512_BEGIN

#if defined(RT_REAL_FLOAT)

// Eight floats: AVX2's lanes (see the top), in functions compiled for AVX-512, which inline them.
using simd_avx2::kLanes;
using simd_avx2::loadLanes, simd_avx2::broadcast, simd_avx2::storeLanes, simd_avx2::andNot, simd_avx2::squareRoot,
    simd_avx2::lessThan, simd_avx2::lessEqual, simd_avx2::notLessThan, simd_avx2::notGreaterThan, simd_avx2::notEqual,
    simd_avx2::laneBits, simd_avx2::select, simd_avx2::minimum, simd_avx2::maximum;
using simd_avx2::RealLanes;

#else

// Eight doubles. A mask stays a register of all-ones lanes, as on SSE2 and AVX2, so that the
// traversal combines masks with the same &, | and andNot on every level: a comparison's k mask
// becomes lanes (AVX512DQ's vpmovm2q), and laneBits and select read the k mask back (vpmovq2m),
// one instruction each way.
inline constexpr int kLanes = 8;
struct RealLanes {
    __m512d v;
};
#define RT_AVX512_OP(name) _mm512_##name##_pd
#define RT_AVX512_COMPARE(a, b, predicate) \
    RealLanes { _mm512_castsi512_pd(_mm512_movm_epi64(_mm512_cmp_pd_mask(a, b, predicate))) }

RT_SIMD_ONE_INTRINSIC_OPERATIONS(RT_AVX512_OP)
RT_SIMD_COMPARISONS(RT_AVX512_COMPARE)
inline __mmask8 kMask(RealLanes mask) { return _mm512_movepi64_mask(_mm512_castpd_si512(mask.v)); }
inline unsigned laneBits(RealLanes mask) { return kMask(mask); }
// The zero-masked forms: GCC 12's plain ones read an undefined register (-Wuninitialized).
inline RealLanes squareRoot(RealLanes a) { return {_mm512_maskz_sqrt_pd(__mmask8(0xff), a.v)}; }
inline RealLanes minimum(RealLanes a, RealLanes b) { return {_mm512_maskz_min_pd(__mmask8(0xff), a.v, b.v)}; }
inline RealLanes maximum(RealLanes a, RealLanes b) { return {_mm512_maskz_max_pd(__mmask8(0xff), a.v, b.v)}; }
inline RealLanes select(RealLanes mask, RealLanes a, RealLanes b) {
    return {_mm512_mask_blend_pd(kMask(mask), b.v, a.v)};
}

#undef RT_AVX512_COMPARE
#undef RT_AVX512_OP

#endif

RT_AVX512_END

}  // namespace simd_avx512

#undef RT_SIMD_COMPARISONS
#undef RT_SIMD_ONE_INTRINSIC_OPERATIONS

#endif

}  // namespace rt
