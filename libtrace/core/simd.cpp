// The packet traversal's choice of lanes (core/simd.h): made once, from the CPU and RT_SIMD.
#include "core/simd.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace rt {

namespace {

SimdLevel defaultLevel() {
    const char* wanted = std::getenv("RT_SIMD");
    if (wanted && std::strcmp(wanted, simdLevelName(SimdLevel::sse2)) == 0) return SimdLevel::sse2;
    return cpuHasAvx2() ? SimdLevel::avx2 : SimdLevel::sse2;
}

std::atomic<SimdLevel>& chosenLevel() {
    static std::atomic<SimdLevel> level{defaultLevel()};
    return level;
}

}  // namespace

bool cpuHasAvx2() {
#if RT_SIMD_AVX2
    // GCC's and clang's check includes the operating system's support for the AVX registers.
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

SimdLevel packetSimd() { return chosenLevel().load(std::memory_order_relaxed); }

bool setPacketSimd(SimdLevel level) {
    if (level == SimdLevel::avx2 && !cpuHasAvx2()) return false;
    chosenLevel().store(level, std::memory_order_relaxed);
    return true;
}

const char* simdLevelName(SimdLevel level) { return level == SimdLevel::avx2 ? "avx2" : "sse2"; }

}  // namespace rt
