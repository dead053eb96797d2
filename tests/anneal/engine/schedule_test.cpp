// The cooling schedule, the portable exp/log behind it and the Metropolis test.
#include <cmath>

#include <gtest/gtest.h>

#include "core/anneal/engine/schedule.h"
#include "core/anneal/random.h"

namespace zomeify {
namespace {

TEST(PortableMath, ExpMatchesLibmWithinTwoUlps)
{
    Rng rng(3);
    for (int i = 0; i < 200000; ++i)
    {
        // Normal results only (below e^−708 ldexp rounds into the subnormals, irrelevant here).
        const double x = -708.0 + 1417.0 * rng.uniform01();
        const double want = std::exp(x), got = portable_exp(x);
        ASSERT_NEAR(got, want, 4.5e-16 * want) << "x = " << x;
    }
    EXPECT_EQ(portable_exp(0.0), 1.0);
    EXPECT_EQ(portable_exp(-800.0), 0.0);
    EXPECT_TRUE(std::isinf(portable_exp(800.0)));
    EXPECT_TRUE(std::isnan(portable_exp(NAN)));
}

TEST(PortableMath, LogMatchesLibmWithinTwoUlps)
{
    Rng rng(5);
    for (int i = 0; i < 200000; ++i)
    {
        const double x = std::ldexp(0.5 + rng.uniform01(), static_cast<int>(rng.below(200)) - 100);
        const double want = std::log(x), got = portable_log(x);
        ASSERT_NEAR(got, want, 4.5e-16 * std::max(1.0, std::fabs(want))) << "x = " << x;
    }
    EXPECT_EQ(portable_log(1.0), 0.0);
    EXPECT_TRUE(std::isinf(portable_log(0.0)));
    EXPECT_TRUE(std::isnan(portable_log(-1.0)));
}

TEST(PortableMath, KnownBitsOnEveryPlatform)
{
    // The same bits natively and in wasm: these constants are what the native build computes.
    EXPECT_EQ(portable_exp(-1.0), 0x1.78b56362cef38p-2);
    EXPECT_EQ(portable_exp(-0.5), 0x1.368b2fc6f960ap-1);
    EXPECT_EQ(portable_log(10.0), 0x1.26bb1bbb55515p+1);
    EXPECT_EQ(CoolingSchedule(0.1, 1e-5).temperature(0.37), 0x1.b2052abfc5b72p-9);
}

TEST(CoolingSchedule, StartsAtT0EndsAtTminGeometricInBetween)
{
    const CoolingSchedule s(2.0, 1e-5);
    EXPECT_EQ(s.temperature(0.0), 2.0);
    EXPECT_EQ(s.temperature(1.0), 1e-5);
    EXPECT_EQ(s.temperature(-1.0), 2.0);
    EXPECT_EQ(s.temperature(7.0), 1e-5);
    // Geometric: T(1/2) is the geometric mean, and T(x + y) · T0 = T(x) · T(y).
    EXPECT_NEAR(s.temperature(0.5), std::sqrt(2.0 * 1e-5), 1e-15);
    EXPECT_NEAR(s.temperature(0.3) * s.temperature(0.4), 2.0 * s.temperature(0.7), 1e-14);
    double last = 3.0;
    for (int i = 0; i <= 1000; ++i)
    {
        const double t = s.temperature(i / 1000.0);
        EXPECT_LT(t, last);
        last = t;
    }
}

TEST(CoolingSchedule, NoSpreadMeansConstantTmin)
{
    const CoolingSchedule s(0.0, 1e-5);
    EXPECT_EQ(s.initial(), 1e-5);
    EXPECT_EQ(s.temperature(0.0), 1e-5);
    EXPECT_EQ(s.temperature(0.5), 1e-5);
}

TEST(Metropolis, DownhillAlwaysUphillWithBoltzmannProbability)
{
    EXPECT_TRUE(metropolis_accept(-1.0, 0.0, 0.999));
    EXPECT_TRUE(metropolis_accept(0.0, 1.0, 0.999));
    EXPECT_FALSE(metropolis_accept(1e-9, 0.0, 0.0));
    EXPECT_FALSE(metropolis_accept(NAN, 1.0, 0.0));
    // u < e^(−ΔE/T): the boundary itself is rejected.
    EXPECT_FALSE(metropolis_accept(1.0, 1.0, portable_exp(-1.0)));
    EXPECT_TRUE(metropolis_accept(1.0, 1.0, std::nextafter(portable_exp(-1.0), 0.0)));

    Rng rng(11);
    const int n = 400000;
    int accepted = 0;
    for (int i = 0; i < n; ++i)
        accepted += metropolis_accept(0.7, 0.5, rng.uniform01());
    const double p = std::exp(-0.7 / 0.5);
    EXPECT_NEAR(static_cast<double>(accepted) / n, p, 5.0 * std::sqrt(p * (1 - p) / n));
}

TEST(DeltaSpread, PopulationStdevInSampleOrder)
{
    DeltaSpread s;
    EXPECT_EQ(s.stdev(), 0.0);
    for (double x : {2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0})
        s.add(x);
    s.add(NAN); // ignored
    EXPECT_EQ(s.count(), 8);
    EXPECT_NEAR(s.stdev(), 2.0, 1e-15);
}

} // namespace
} // namespace zomeify
