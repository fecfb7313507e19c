// Lanes of Real for the leaf tests (geometry/triangle_block.h): the few operations they
// need, on one SSE2 register (every x86-64 CPU has SSE2, so the default build runs anywhere
// without choosing code at run time): two lanes with Real = double, four with float; and
// four in plain C++ elsewhere. Each lane rounds exactly as the scalar code does (IEEE add,
// sub, mul, div, no fused multiply-add), so a lane's answer has the scalar test's bits: the
// trees and the naive list agree to the last bit.
//
// Why not AVX2 or AVX-512: the default build must run on any x86-64, so wider lanes need
// run-time dispatch (a second copy of the traversal compiled for the wider ISA); kept for
// later, the leaf layout (blocks of kSimdWidth) is ready for it. Why one register and not
// two for double: a leaf holds few triangles (2-3 in a KD tree), so wider blocks would
// mostly test and store empty lanes.
#pragma once

#include "core/real.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#define RT_SIMD_SSE2 1
#endif

namespace rt {

#if RT_SIMD_SSE2 && !defined(RT_REAL_FLOAT)

inline constexpr int kSimdWidth = 2;
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

#elif RT_SIMD_SSE2

inline constexpr int kSimdWidth = 4;
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

#else

// The portable path: a mask lane is 1 or 0.
inline constexpr int kSimdWidth = 4;
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

#endif

}  // namespace rt
