// Seed slabs split the live nodes among the threads: in every epoch each live node is in exactly
// one thread's slab, slabs are balanced, and over successive epochs a thread's slab moves.
#include <algorithm>
#include <set>

#include <gtest/gtest.h>

#include "core/anneal/engine/seed_slabs.h"
#include "core/mesh/model_convert.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify {
namespace {

TEST(SeedSlabs, EveryLiveNodeInExactlyOneSlab)
{
    ZomeMesh mesh = from_model(fixtures::cube_shell(4));
    mesh.remove_vertex(Vertex(3)); // a deleted slot is never a seed (the hole does not matter here)
    const size_t live = mesh.n_vertices();
    for (int threads : {1, 2, 3, 8})
        for (uint64_t epoch = 0; epoch < 14; ++epoch)
        {
            std::multiset<MeshIndex> seen;
            for (int t = 0; t < threads; ++t)
            {
                const std::vector<MeshIndex> slab = seed_slab(mesh, epoch, t, threads);
                EXPECT_LE(slab.size(), live / threads + 1);
                EXPECT_GE(slab.size(), live / threads);
                seen.insert(slab.begin(), slab.end());
            }
            EXPECT_EQ(seen.size(), live);
            EXPECT_EQ(std::set<MeshIndex>(seen.begin(), seen.end()).size(), live);
            EXPECT_EQ(seen.count(3), 0u);
        }
}

TEST(SeedSlabs, SlabsMoveWithTheEpoch)
{
    const ZomeMesh mesh = from_model(fixtures::cube_shell(4));
    std::set<std::vector<MeshIndex>> distinct;
    for (uint64_t epoch = 0; epoch < 12; ++epoch)
    {
        std::vector<MeshIndex> slab = seed_slab(mesh, epoch, 0, 2);
        std::sort(slab.begin(), slab.end());
        distinct.insert(slab);
    }
    EXPECT_GE(distinct.size(), 6u);
}

} // namespace
} // namespace zomeify
