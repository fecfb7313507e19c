#include "render/sampling.h"

#include <cmath>
#include <set>

#include "test_util.h"

using namespace rt;

TEST(Sampling, StreamsDependOnlyOnPixelAndSample) {
    SampleRng a{3, 4, 5}, b{3, 4, 5};
    for (int i = 0; i < 10; ++i) EXPECT_EQ(a.next(), b.next());
    std::set<std::uint64_t> firsts;
    for (std::uint32_t x = 0; x < 8; ++x)
        for (std::uint32_t y = 0; y < 8; ++y)
            for (std::uint32_t s = 0; s < 4; ++s) firsts.insert(SampleRng{x, y, s}.next());
    EXPECT_EQ(firsts.size(), 8u * 8u * 4u);  // neighbouring pixels and samples do not share streams
}

TEST(Sampling, UniformStaysInTheUnitInterval) {
    SampleRng rng{1, 2, 3};
    double sum = 0;
    for (int i = 0; i < 10000; ++i) {
        const Real u = rng.uniform();
        ASSERT_GE(u, 0);
        ASSERT_LT(u, 1);
        sum += double(u);
    }
    EXPECT_NEAR(sum / 10000, 0.5, 0.02);
}

TEST(Sampling, BoxMullerGivesStandardNormalNumbers) {
    SampleRng rng{7, 7, 7};
    double sum = 0, sumSq = 0;
    const int n = 20000;
    for (int i = 0; i < n / 2; ++i) {
        Real a, b;
        rng.normalPair(a, b);
        ASSERT_TRUE(std::isfinite(a) && std::isfinite(b));
        sum += double(a) + double(b);
        sumSq += double(a) * double(a) + double(b) * double(b);
    }
    EXPECT_NEAR(sum / n, 0.0, 0.03);
    EXPECT_NEAR(sumSq / n, 1.0, 0.05);
}

TEST(Sampling, JitteredGridPutsOneSamplePerCell) {
    SampleRng rng{0, 0, 0};
    std::set<std::pair<int, int>> cells;
    for (int i = 0; i < 9; ++i) {
        Real x, y;
        jitteredGridSample(i, 9, rng, x, y);
        ASSERT_GE(x, 0);
        ASSERT_LT(x, 1);
        ASSERT_GE(y, 0);
        ASSERT_LT(y, 1);
        cells.insert({int(x * 3), int(y * 3)});
    }
    EXPECT_EQ(cells.size(), 9u);
}

TEST(Sampling, OrthonormalBasisIsOrthonormal) {
    for (const Vec3& n : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, normalize(Vec3{1, 2, 3}), normalize(Vec3{-3, 0.1, -0.2})}) {
        Vec3 t, b;
        orthonormalBasis(n, t, b);
        EXPECT_NEAR(dot(t, n), 0, kTol);
        EXPECT_NEAR(dot(b, n), 0, kTol);
        EXPECT_NEAR(dot(t, b), 0, kTol);
        EXPECT_NEAR(length(t), 1, kTol);
        EXPECT_NEAR(length(b), 1, kTol);
    }
}
