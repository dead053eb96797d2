#include "core/zome/tables.h"

#include <gtest/gtest.h>

using namespace zomeify;

TEST(Tables, SplitVectorMatchesThePaper)
{
    const ZomeTables& t = ZomeTables::get();
    EXPECT_EQ(t.split_total(), 8472u);
    // The paper's per-kind figures are the number of splits of each single vector of that kind
    // (30·(30 + 54 + 36) + 20·(38 + 56 + 44) + 12·(62 + 72 + 42) = 8472).
    const size_t expected[] = {30, 54, 36, 38, 56, 44, 62, 72, 42};
    for (int v = 0; v < kVectorCount; ++v)
    {
        for (const VecPair& p : t.split(v))
            EXPECT_EQ(zome_vector(p.first) + zome_vector(p.second), zome_vector(v));
        EXPECT_EQ(t.split(v).size(), expected[static_cast<int>(vector_kind(v))])
            << "vector " << v << " of kind " << kind_info(vector_kind(v)).name;
    }
    // Collinear splits are included: b2 = b0 + b1 and b2 = b1 + b0.
    const int b2 = vector_id(0, 2), b1 = vector_id(0, 1), b0 = vector_id(0, 0);
    bool found01 = false, found10 = false;
    for (const VecPair& p : t.split(b2))
    {
        found01 |= p.first == b0 && p.second == b1;
        found10 |= p.first == b1 && p.second == b0;
    }
    EXPECT_TRUE(found01 && found10);
}

TEST(Tables, MergeVectorsIsTheInverse)
{
    const ZomeTables& t = ZomeTables::get();
    EXPECT_EQ(t.merge_keys(), 8472u);
    for (int a = 0; a < kVectorCount; ++a)
        for (int b = 0; b < kVectorCount; ++b)
        {
            const int m = t.merge(a, b);
            const int direct = vector_id_of(zome_vector(a) + zome_vector(b));
            EXPECT_EQ(m, direct);
        }
}

TEST(Tables, ChangeDirectionsMatchesThePaper)
{
    const ZomeTables& t = ZomeTables::get();
    EXPECT_EQ(t.change_total(), 686184u);
    // Spot-check the definition on a few keys against brute force.
    for (int a = 0; a < kVectorCount; a += 17)
        for (int b = 0; b < kVectorCount; b += 13)
        {
            const ZVec sum = zome_vector(a) + zome_vector(b);
            size_t brute = 0;
            if (a != b && !sum.is_zero())
                for (int x = 0; x < kVectorCount; ++x)
                    for (int y = 0; y < kVectorCount; ++y)
                        brute += (x != a || y != b) && zome_vector(x) + zome_vector(y) == sum;
            size_t visited = 0;
            t.for_each_change(a, b, [&](VecPair p) {
                EXPECT_EQ(zome_vector(p.first) + zome_vector(p.second), sum);
                EXPECT_FALSE(p.first == a && p.second == b);
                ++visited;
            });
            EXPECT_EQ(visited, brute);
            EXPECT_EQ(t.change_count(a, b), brute);
        }
}

TEST(Tables, SafeToShareBetweenThreadsBecauseImmutable)
{
    // get() returns the same const object every time; construction is a function-local static.
    EXPECT_EQ(&ZomeTables::get(), &ZomeTables::get());
    EXPECT_GT(ZomeTables::get().memory_bytes(), 0u);
}
