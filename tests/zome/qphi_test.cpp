#include "core/zome/qphi.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

using namespace zomeify;

TEST(QPhi, FieldIdentities)
{
    const QPhi phi{0, 1};
    EXPECT_EQ(phi * phi, (QPhi{1, 1}));           // φ² = φ + 1
    EXPECT_EQ(phi * (QPhi{-1, 1}), (QPhi{1, 0})); // φ(φ − 1) = 1
    EXPECT_EQ(phi_power(3), (QPhi{1, 2}));
    EXPECT_EQ(phi_power(-1), (QPhi{-1, 1}));
    EXPECT_EQ(phi_power(5) * phi_power(-5), (QPhi{1, 0}));
    EXPECT_EQ((QPhi{7, -3}).times_phi().div_phi(), (QPhi{7, -3}));
}

TEST(QPhi, SignAndOrderAreExact)
{
    EXPECT_EQ((QPhi{0, 0}).sign(), 0);
    EXPECT_EQ((QPhi{-1, 1}).sign(), 1);  // 1/φ
    EXPECT_EQ((QPhi{2, -1}).sign(), 1);  // 2 − φ
    EXPECT_EQ((QPhi{-2, 1}).sign(), -1); // φ − 2
    // Consecutive Fibonacci numbers: F(n+1) − F(n)·φ = (−1/φ)^n, tiny and alternating in sign.
    EXPECT_EQ((QPhi{832040, -514229}).sign(), -1); // n = 29
    EXPECT_EQ((QPhi{-832040, 514229}).sign(), 1);
    EXPECT_EQ((QPhi{1346269, -832040}).sign(), 1); // n = 30
    EXPECT_LT(compare(QPhi{1, 1}, QPhi{3, 0}), 0); // φ² < 3
    EXPECT_GT(compare(QPhi{0, 2}, QPhi{3, 0}), 0); // 2φ > 3
    for (int a = -20; a <= 20; ++a)
        for (int b = -20; b <= 20; ++b)
        {
            const double v = a + b * kPhi;
            EXPECT_EQ((QPhi{a, b}).sign(), (v > 0) - (v < 0)) << a << " " << b;
        }
}

TEST(QPhi, OverflowIsDetected)
{
    const int64_t big = std::numeric_limits<int64_t>::max() / 2 + 1;
    EXPECT_THROW((QPhi{big, 0}) + (QPhi{big, 0}), OverflowError);
    EXPECT_THROW((QPhi{0, big}) * (QPhi{0, 4}), OverflowError);
    EXPECT_THROW((QPhi{0, big}).sign(), OverflowError);
}
