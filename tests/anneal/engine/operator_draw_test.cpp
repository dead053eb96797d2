// The weighted draw of the operator kind (operator_draw.h).
#include <array>
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "core/anneal/engine/operator_draw.h"

namespace zomeify {
namespace {

TEST(OperatorDraw, EqualWeightsAreThePapersUniformDraw)
{
    // Same kinds, and the same random stream afterwards, as one below(7) per draw.
    const OperatorDraw draw({3, 3, 3, 3, 3, 3, 3});
    Rng a(11), b(11);
    for (int i = 0; i < 10000; ++i)
        ASSERT_EQ(static_cast<int>(draw.draw(a)), static_cast<int>(b.below(kOperatorKinds)));
    EXPECT_EQ(a.next(), b.next());
}

TEST(OperatorDraw, FrequenciesFollowTheWeightsAndZeroIsNeverDrawn)
{
    const std::array<uint32_t, kOperatorKinds> weights{2, 1, 2, 1, 0, 4, 2};
    const OperatorDraw draw(weights);
    Rng rng(5);
    std::array<int, kOperatorKinds> counts{};
    constexpr int kDraws = 120000;
    for (int i = 0; i < kDraws; ++i)
        ++counts[static_cast<size_t>(draw.draw(rng))];
    EXPECT_EQ(counts[static_cast<size_t>(OperatorKind::FlipDiag)], 0);
    for (int k = 0; k < kOperatorKinds; ++k)
    {
        const double expected = kDraws * weights[k] / 12.0;
        EXPECT_NEAR(counts[k], expected, 5.0 * std::sqrt(expected) + 1.0) << "kind " << k;
    }
}

TEST(OperatorDraw, AllZeroWeightsAreRefused)
{
    EXPECT_THROW(OperatorDraw({0, 0, 0, 0, 0, 0, 0}), std::invalid_argument);
}

} // namespace
} // namespace zomeify
