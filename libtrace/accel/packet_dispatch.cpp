// SplitTree::intersectPacket and occludedPacket: the packet traversals (kd_packet.cpp) on the
// lanes core/simd.h's packetSimd() chooses, by default the widest the CPU has: AVX-512, AVX2 or
// SSE2. Apart from kd_packet.cpp, which is compiled once per set of lanes and holds only that
// set's traversals.
#include "accel/split_tree.h"

namespace rt {

void SplitTree::intersectPacket(const Ray* rays, int count, Real tMax, Hit* hits, bool* found,
                                RayCounters& counters) const {
#if RT_SIMD_AVX512
    if (packetSimd() == SimdLevel::avx512)
        return tracePacket<SimdLevel::avx512>(rays, count, tMax, hits, found, counters);
#endif
#if RT_SIMD_AVX2
    if (packetSimd() == SimdLevel::avx2) return tracePacket<SimdLevel::avx2>(rays, count, tMax, hits, found, counters);
#endif
    tracePacket<SimdLevel::sse2>(rays, count, tMax, hits, found, counters);
}

void SplitTree::occludedPacket(const Ray* rays, int count, const Real* tMax, bool* blocked,
                               RayCounters& counters) const {
#if RT_SIMD_AVX512
    if (packetSimd() == SimdLevel::avx512)
        return traceShadowPacket<SimdLevel::avx512>(rays, count, tMax, blocked, counters);
#endif
#if RT_SIMD_AVX2
    if (packetSimd() == SimdLevel::avx2)
        return traceShadowPacket<SimdLevel::avx2>(rays, count, tMax, blocked, counters);
#endif
    traceShadowPacket<SimdLevel::sse2>(rays, count, tMax, blocked, counters);
}

}  // namespace rt
