// Seed slabs: in every epoch each live node is in exactly one slab, slabs are balanced and listed in
// index order, threads are spread over the slabs, and over successive epochs a thread's slab moves.
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
    for (int slabs : {1, 2, 3, 8})
        for (uint64_t epoch = 0; epoch < 30; ++epoch)
        {
            std::multiset<MeshIndex> seen;
            for (int k = 0; k < slabs; ++k)
            {
                const std::vector<MeshIndex> slab = seed_slab(mesh, epoch, k, slabs);
                EXPECT_LE(slab.size(), live / slabs + 1);
                EXPECT_GE(slab.size(), live / slabs);
                EXPECT_TRUE(std::is_sorted(slab.begin(), slab.end()));
                seen.insert(slab.begin(), slab.end());
            }
            EXPECT_EQ(seen.size(), live);
            EXPECT_EQ(std::set<MeshIndex>(seen.begin(), seen.end()).size(), live);
            EXPECT_EQ(seen.count(3), 0u);
        }
}

TEST(SeedSlabs, ThreadsTakeDistinctSlabsThatMoveOn)
{
    for (int threads : {1, 2, 3, 4, 8})
    {
        const SlabPlan plan = slab_plan(400, threads);
        EXPECT_GE(plan.slabs, threads);
        EXPECT_EQ(plan.epoch_proposals, 125u * 400u);
        for (uint64_t epoch = 0; epoch < 20; ++epoch)
        {
            std::set<int> taken;
            for (int t = 0; t < threads; ++t)
            {
                const int slab = slab_of_thread(epoch, t, threads, plan.slabs);
                EXPECT_EQ(slab_of_thread(epoch + 1, t, threads, plan.slabs), (slab + 1) % plan.slabs);
                taken.insert(slab);
            }
            EXPECT_EQ(taken.size(), static_cast<size_t>(threads));
        }
    }
    EXPECT_EQ(slab_plan(3, 1).epoch_proposals, 4096u);
}

TEST(SeedSlabs, SweepsCutAlongChangingDirections)
{
    const ZomeMesh mesh = from_model(fixtures::cube_shell(4));
    std::set<std::vector<MeshIndex>> distinct;
    for (uint64_t epoch = 0; epoch < 24; epoch += 2)
        distinct.insert(seed_slab(mesh, epoch, 0, 2));
    EXPECT_GE(distinct.size(), 5u);
}

} // namespace
} // namespace zomeify
