// portable_angle against libm's atan2: the same angle to a few ulp, including the edge cases.
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "core/base/portable_math.h"

namespace zomeify {
namespace {

TEST(PortableMath, AngleAgreesWithAtan2)
{
    uint64_t state = 88172645463325252ull; // xorshift: the same inputs on every platform
    auto next = [&state] {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return static_cast<double>(state >> 11) / 9007199254740992.0; // [0, 1)
    };
    const double scales[] = {1.0, 1e-9, 1e9};
    double worst = 0.0;
    for (int i = 0; i < 200000; ++i)
    {
        const double y = next() * scales[i % 3];
        const double x = (2.0 * next() - 1.0) * scales[(i / 3) % 3];
        const double expected = std::atan2(y, x);
        worst = std::max(worst, std::abs(portable_angle(y, x) - expected) / expected);
    }
    EXPECT_LT(worst, 2e-15); // under 10 ulp
    EXPECT_EQ(portable_angle(0.0, 1.0), 0.0);
    EXPECT_EQ(portable_angle(0.0, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(portable_angle(0.0, -1.0), M_PI);
    EXPECT_DOUBLE_EQ(portable_angle(1.0, 0.0), M_PI / 2);
    EXPECT_DOUBLE_EQ(portable_angle(1.0, 1.0), M_PI / 4);
    EXPECT_DOUBLE_EQ(portable_angle(1.0, -1.0), 3 * M_PI / 4);
    EXPECT_DOUBLE_EQ(portable_angle(1e-300, -1.0), M_PI);
    EXPECT_DOUBLE_EQ(portable_angle(1.0, 1e-300), M_PI / 2);
}

} // namespace
} // namespace zomeify
