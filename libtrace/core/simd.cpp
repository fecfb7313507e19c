// The traversals' choice of lanes (core/simd.h): made once, from the CPU and RT_SIMD.
#include "core/simd.h"

#include <atomic>
#include <cstdlib>
#include <cstring>

namespace rt {

namespace {

// The level RT_SIMD names if the CPU has it, else the widest the CPU has.
SimdLevel defaultLevel() {
    const char* wanted = std::getenv("RT_SIMD");
    for (SimdLevel level : kSimdLevels)
        if (wanted && std::strcmp(wanted, simdLevelName(level)) == 0 && cpuHas(level)) return level;
    for (SimdLevel level : {SimdLevel::avx512, SimdLevel::avx2})
        if (cpuHas(level)) return level;
    return SimdLevel::sse2;
}

std::atomic<SimdLevel>& chosenLevel() {
    static std::atomic<SimdLevel> level{defaultLevel()};
    return level;
}

}  // namespace

bool cpuHas(SimdLevel level) {
    switch (level) {
        case SimdLevel::sse2:
            return true;  // simd_base: SSE2 on x86-64, plain C++ elsewhere
#if RT_SIMD_AVX2
        // GCC's and clang's check includes the operating system's support for the AVX
        // registers (and for AVX-512's ZMM and k registers).
        case SimdLevel::avx2:
            return __builtin_cpu_supports("avx2");
        case SimdLevel::avx512:  // what RT_AVX512_BEGIN compiles for
            return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
                   __builtin_cpu_supports("avx512vl");
#endif
        default:
            return false;
    }
}

SimdLevel simdLevel() { return chosenLevel().load(std::memory_order_relaxed); }

bool setSimdLevel(SimdLevel level) {
    if (!cpuHas(level)) return false;
    chosenLevel().store(level, std::memory_order_relaxed);
    return true;
}

const char* simdLevelName(SimdLevel level) {
    switch (level) {
        case SimdLevel::avx2:
            return "avx2";
        case SimdLevel::avx512:
            return "avx512";
        default:
            return "sse2";
    }
}

}  // namespace rt
