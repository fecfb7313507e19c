// core/simd.h: the AVX2 and AVX-512 lanes of the packet traversal give, lane by lane, the scalar
// operations' bits (arithmetic) and answers (comparisons, NaN and infinities included), as the SSE2 lanes do;
// and the choice of lanes follows the CPU.
#include "core/simd.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "test_util.h"

using namespace rt;

namespace {

// Operations on lanes a and b, one output row each: + - * / < <= !< !> != and select(a < b, a, b),
// and the square root of a.
constexpr int kOps = 11;
constexpr int kMaxLanes = 8;
using LaneOps = void (*)(const Real* a, const Real* b, Real (*out)[kMaxLanes]);

// LANES##Ops: the operations on namespace LANES's lanes, defined between its level's BEGIN and END.
#define RT_LANE_OPS(LANES)                                                         \
    void LANES##Ops(const Real* a, const Real* b, Real(*out)[kMaxLanes]) {         \
        using LANES::RealLanes;                                                    \
        const RealLanes x = LANES::loadLanes(a), y = LANES::loadLanes(b);          \
        const RealLanes results[kOps] = {x + y,                                    \
                                         x - y,                                    \
                                         x * y,                                    \
                                         x / y,                                    \
                                         lessThan(x, y),                           \
                                         lessEqual(x, y),                          \
                                         notLessThan(x, y),                        \
                                         notGreaterThan(x, y),                     \
                                         notEqual(x, y),                           \
                                         select(lessThan(x, y), x, y),             \
                                         squareRoot(x)};                           \
        for (int op = 0; op < kOps; ++op) LANES::storeLanes(out[op], results[op]); \
    }

#if RT_SIMD_AVX2
RT_AVX2_BEGIN
RT_LANE_OPS(simd_avx2)
RT_AVX2_END
RT_AVX512_BEGIN
RT_LANE_OPS(simd_avx512)
RT_AVX512_END
#endif

// What a lane of each operation must hold: the scalar result, or for a comparison a mask lane
// that is all ones exactly when the scalar comparison holds.
bool laneAgrees(int op, Real a, Real b, Real lane) {
    const auto same = [](Real x, Real y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    Real allOnes;
    std::memset(&allOnes, 0xff, sizeof allOnes);
    const auto mask = [&](bool set) { return same(lane, set ? allOnes : Real(0)); };
    switch (op) {
        case 0:
            return same(lane, a + b);
        case 1:
            return same(lane, a - b);
        case 2:
            return same(lane, a * b);
        case 3:
            return same(lane, a / b);
        case 4:
            return mask(a < b);
        case 5:
            return mask(a <= b);
        case 6:
            return mask(!(a < b));
        case 7:
            return mask(!(a > b));
        case 8:
            return mask(a != b);
        case 9:
            return same(lane, a < b ? a : b);
        default:
            return same(lane, std::sqrt(a));
    }
}

// The lanes of `ops` that differ from the scalar operations, on every pair of special and
// ordinary values: zeros of both signs, infinities, NaN, subnormals, the largest finite value.
int differingLanes(LaneOps ops, int lanes) {
    const Real inf = std::numeric_limits<Real>::infinity(), nan = std::numeric_limits<Real>::quiet_NaN();
    const Real tiny = std::numeric_limits<Real>::denorm_min(), smallest = std::numeric_limits<Real>::min();
    const std::vector<Real> values = {0,
                                      Real(-0.0),
                                      1,
                                      -1,
                                      Real(0.1),
                                      Real(3e-7),
                                      Real(1) / 3,
                                      inf,
                                      -inf,
                                      nan,
                                      tiny,
                                      -tiny,
                                      smallest / 3,
                                      smallest,
                                      std::numeric_limits<Real>::max()};
    // Every pair of values, lane by lane, `lanes` pairs at a time.
    std::vector<Real> as, bs;
    for (Real a : values)
        for (Real b : values) as.push_back(a), bs.push_back(b);
    while (as.size() % lanes != 0) as.push_back(1), bs.push_back(2);
    int differing = 0;
    for (std::size_t first = 0; first < as.size(); first += lanes) {
        Real out[kOps][kMaxLanes];
        ops(&as[first], &bs[first], out);
        for (int op = 0; op < kOps; ++op)
            for (int lane = 0; lane < lanes; ++lane)
                differing += !laneAgrees(op, as[first + lane], bs[first + lane], out[op][lane]);
    }
    return differing;
}

}  // namespace

TEST(Simd, Avx2LanesHaveTheScalarOperationsBits) {
#if RT_SIMD_AVX2
    if (!cpuHas(SimdLevel::avx2)) GTEST_SKIP() << "this CPU has no AVX2";
    EXPECT_EQ(differingLanes(simd_avx2Ops, simd_avx2::kLanes), 0);
#else
    GTEST_SKIP() << "no AVX2 lanes on this platform";
#endif
}

TEST(Simd, Avx512LanesHaveTheScalarOperationsBits) {
#if RT_SIMD_AVX512
    if (!cpuHas(SimdLevel::avx512)) GTEST_SKIP() << "this CPU has no AVX-512 (F, DQ and VL)";
    EXPECT_EQ(differingLanes(simd_avx512Ops, simd_avx512::kLanes), 0);
#else
    GTEST_SKIP() << "no AVX-512 lanes on this platform";
#endif
}

// Each level can be chosen exactly where the CPU has it; SSE2 always.
TEST(Simd, LevelsFollowTheCpu) {
    const SimdLevel before = simdLevel();
    EXPECT_TRUE(cpuHas(SimdLevel::sse2));
    for (SimdLevel level : kSimdLevels) {
        EXPECT_TRUE(setSimdLevel(SimdLevel::sse2));
        EXPECT_EQ(setSimdLevel(level), cpuHas(level)) << simdLevelName(level);  // refused where the CPU lacks it
        EXPECT_EQ(simdLevel(), cpuHas(level) ? level : SimdLevel::sse2) << simdLevelName(level);
    }
    setSimdLevel(before);
}
