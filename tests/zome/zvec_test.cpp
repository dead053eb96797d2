#include "core/zome/zvec.h"

#include <limits>
#include <unordered_set>

#include <gtest/gtest.h>

#include "core/zome/slots.h"

using namespace zomeify;

TEST(ZVec, SixIntegerConvention)
{
    const ZVec b0x{{0, 2, 0, 0, 0, 0}}; // design.md §2
    const ZVec b1x{{2, 0, 0, 0, 0, 0}};
    EXPECT_EQ(b0x.times_phi(), b1x);
    EXPECT_EQ(b1x.div_phi(), b0x);
    EXPECT_DOUBLE_EQ(b1x.coord(0), kPhi);
    EXPECT_EQ(norm4(b0x), (QPhi{4, 0}));
    EXPECT_EQ(norm4(b1x), (QPhi{4, 4})); // 4φ²
    EXPECT_EQ(vector_kind(vector_id_of(b0x)), StrutKind::B0);
    EXPECT_EQ(vector_kind(vector_id_of(b1x)), StrutKind::B1);
}

TEST(ZVec, ArithmeticAndHash)
{
    const ZVec a{{1, 2, 3, 4, 5, 6}}, b{{-1, 0, 2, -4, 7, 1}};
    EXPECT_EQ(a + b - b, a);
    EXPECT_EQ(-(-a), a);
    EXPECT_TRUE((a - a).is_zero());
    std::unordered_set<ZVec, ZVecHash> set;
    for (int i = -5; i <= 5; ++i)
        for (int j = -5; j <= 5; ++j)
            set.insert(ZVec{{i, j, j, i, 0, 1}});
    EXPECT_EQ(set.size(), 121u);
}

TEST(ZVec, OverflowIsDetected)
{
    const int32_t m = std::numeric_limits<int32_t>::max();
    const ZVec big{{m, m, 0, 0, 0, 0}};
    const ZVec one{{1, 0, 0, 0, 0, 0}};
    EXPECT_THROW(big + one, OverflowError);
    EXPECT_THROW(big.times_phi(), OverflowError);
}

TEST(ZVec, NormsOfTheNineStrutKinds)
{
    for (int id = 0; id < kVectorCount; ++id)
    {
        const StrutKindInfo& info = kind_info(vector_kind(id));
        EXPECT_EQ(norm4(zome_vector(id)), info.length4) << "vector " << id;
    }
}
