#include "core/mesh/position_index.h"

#include <atomic>
#include <random>
#include <thread>
#include <unordered_map>

#include <gtest/gtest.h>

using namespace zomeify;

namespace {

ZVec point(int i) { return ZVec{{i % 7, i / 7 % 11, i / 77, -i, 2 * i, 3}}; }

} // namespace

TEST(MeshPositionIndex, MatchesAReferenceMapUnderChurn)
{
    PositionIndex index;
    std::unordered_map<ZVec, Vertex, ZVecHash> ref;
    std::mt19937 rng(3);
    for (int step = 0; step < 200000; ++step)
    {
        const ZVec p = point(static_cast<int>(rng() % 5000));
        const unsigned op = rng() % 3;
        if (op == 0)
            EXPECT_EQ(index.insert(p, Vertex(static_cast<MeshIndex>(step))),
                      ref.emplace(p, Vertex(static_cast<MeshIndex>(step))).second);
        else if (op == 1)
            EXPECT_EQ(index.erase(p), ref.erase(p) == 1);
        else
        {
            const auto it = ref.find(p);
            EXPECT_EQ(index.find(p), it == ref.end() ? Vertex() : it->second);
        }
        ASSERT_EQ(index.size(), ref.size());
    }
    size_t visited = 0;
    index.for_each([&](const ZVec& p, Vertex v) {
        EXPECT_EQ(ref.at(p), v);
        ++visited;
    });
    EXPECT_EQ(visited, ref.size());
    index.clear();
    EXPECT_EQ(index.size(), 0u);
    EXPECT_FALSE(index.find(point(1)).is_valid());
}

TEST(MeshPositionIndex, ReadersRunDuringCommits)
{
    // One writer inserts and erases "churn" points while readers look up "stable" points (always
    // present) and "absent" points (never inserted). Capacity is reserved so nothing rehashes.
    const int n_stable = 2000, n_churn = 2000;
    PositionIndex index;
    index.reserve(n_stable + 4 * n_churn);
    for (int i = 0; i < n_stable; ++i)
        index.insert(point(i), Vertex(static_cast<MeshIndex>(i)));
    std::atomic<bool> stop{false};
    std::atomic<size_t> wrong{0};
    const auto reader = [&] {
        size_t k = 0;
        while (!stop.load(std::memory_order_relaxed))
        {
            const int i = static_cast<int>(k++ % n_stable);
            if (index.find(point(i)) != Vertex(static_cast<MeshIndex>(i)))
                ++wrong;
            if (index.find(point(100000 + i)).is_valid())
                ++wrong;
        }
    };
    std::thread r1(reader), r2(reader);
    for (int round = 0; round < 2; ++round)
        for (int i = 0; i < n_churn; ++i)
        {
            const ZVec p = point(50000 + i);
            if (round == 0)
            {
                ASSERT_TRUE(index.has_capacity_for(1));
                index.insert(p, Vertex(static_cast<MeshIndex>(i)));
            }
            else
                index.erase(p);
        }
    stop = true;
    r1.join();
    r2.join();
    EXPECT_EQ(wrong.load(), 0u);
    EXPECT_EQ(index.size(), static_cast<size_t>(n_stable));
}
