// core/simd.h: the AVX2 lanes of the packet traversal give, lane by lane, the scalar operations'
// bits (arithmetic) and answers (comparisons, NaN and infinities included), as the SSE2 lanes do;
// and the choice of lanes follows the CPU.
#include "core/simd.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "test_util.h"

using namespace rt;

namespace {

// Operations on lanes a and b, one output row each: + - * / < <= !< !> != and select(a < b, a, b).
constexpr int kOps = 10;

#if RT_SIMD_AVX2
RT_AVX2_BEGIN
void avx2Ops(const Real* a, const Real* b, Real (*out)[simd_avx2::kLanes]) {
    using simd_avx2::RealLanes;
    const RealLanes x = simd_avx2::loadLanes(a), y = simd_avx2::loadLanes(b);
    const RealLanes results[kOps] = {x + y,
                                     x - y,
                                     x * y,
                                     x / y,
                                     lessThan(x, y),
                                     lessEqual(x, y),
                                     notLessThan(x, y),
                                     notGreaterThan(x, y),
                                     notEqual(x, y),
                                     select(lessThan(x, y), x, y)};
    for (int op = 0; op < kOps; ++op) simd_avx2::storeLanes(out[op], results[op]);
}
RT_AVX2_END
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
        default:
            return same(lane, a < b ? a : b);
    }
}

}  // namespace

TEST(Simd, Avx2LanesHaveTheScalarOperationsBits) {
#if RT_SIMD_AVX2
    if (!cpuHasAvx2()) GTEST_SKIP() << "this CPU has no AVX2";
    const Real inf = std::numeric_limits<Real>::infinity(), nan = std::numeric_limits<Real>::quiet_NaN();
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
                                      std::numeric_limits<Real>::denorm_min(),
                                      std::numeric_limits<Real>::max()};
    // Every pair of values, lane by lane, kLanes pairs at a time.
    std::vector<Real> as, bs;
    for (Real a : values)
        for (Real b : values) as.push_back(a), bs.push_back(b);
    while (as.size() % simd_avx2::kLanes != 0) as.push_back(1), bs.push_back(2);
    int differing = 0;
    for (std::size_t first = 0; first < as.size(); first += simd_avx2::kLanes) {
        Real out[kOps][simd_avx2::kLanes];
        avx2Ops(&as[first], &bs[first], out);
        for (int op = 0; op < kOps; ++op)
            for (int lane = 0; lane < simd_avx2::kLanes; ++lane)
                differing += !laneAgrees(op, as[first + lane], bs[first + lane], out[op][lane]);
    }
    EXPECT_EQ(differing, 0);
#else
    GTEST_SKIP() << "no AVX2 lanes on this platform";
#endif
}

TEST(Simd, PacketLanesFollowTheCpu) {
    const SimdLevel before = packetSimd();
    EXPECT_TRUE(setPacketSimd(SimdLevel::sse2));
    EXPECT_EQ(packetSimd(), SimdLevel::sse2);
    EXPECT_EQ(setPacketSimd(SimdLevel::avx2), cpuHasAvx2());  // refused where the CPU lacks it
    EXPECT_EQ(packetSimd(), cpuHasAvx2() ? SimdLevel::avx2 : SimdLevel::sse2);
    setPacketSimd(before);
}
