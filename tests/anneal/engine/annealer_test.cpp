// The annealer on shared meshes: determinism (a golden hash, the same natively and in wasm),
// invariants and exact energy sums after a run, cancel, and the best model. Budgets are proposal
// counts, never wall time, so slow builds (sanitizers, wasm) take longer but decide the same.
#include <atomic>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <thread>

#include <gtest/gtest.h>

#include "core/anneal/engine/annealer.h"
#include "core/anneal/engine/fold_overs.h"
#include "core/anneal/engine/model_hash.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "tests/anneal/engine/anneal_scene.h"
#include "tests/support/paths.h"

namespace zomeify {
namespace {

const test::AnnealScene& bunny8()
{
    static const auto scene = test::make_anneal_scene("bunny.obj", 8);
    return *scene;
}

AnnealOptions deterministic_options(uint64_t proposals)
{
    AnnealOptions o;
    o.threads = 1;
    o.seed = 7;
    o.max_proposals = proposals;
    o.target_nodes = 392; // the paper's bunny
    return o;
}

// The canonical hash of the bunny (8 cells, Z0 of 210 nodes: the plain grid carved freely) after 30,000 proposals with
// seed 7 and one thread. The same constant must come out natively and in wasm; it changes legitimately when an
// operator, the energy, the schedule or the random stream changes (then update it, once, from the native run's printed
// value, and check that wasm agrees).
constexpr uint64_t kBunnyGoldenHash = 0x6ef8ded0e48133cfULL;

TEST(Annealer, OneThreadFixedSeedIsBitIdentical)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    Annealer first(scene.z0, *scene.context, deterministic_options(30000));
    const AnnealResult a = first.run();
    Annealer second(scene.z0, *scene.context, deterministic_options(30000));
    const AnnealResult b = second.run();
    const uint64_t hash = canonical_model_hash(a.model);
    std::printf("bunny golden hash: 0x%016" PRIx64 " (%zu nodes, %" PRIu64 " commits, E %.6f -> %.6f)\n", hash,
                a.model.nodes.size(), a.stats.commits, a.start.total, a.end.total);
    EXPECT_EQ(hash, canonical_model_hash(b.model));
    EXPECT_EQ(a.end.sums, b.end.sums);
    EXPECT_EQ(a.stats.proposals, 30000U);
    EXPECT_GT(a.stats.commits, 0U);
    EXPECT_EQ(hash, kBunnyGoldenHash) << "see the comment at kBunnyGoldenHash";
}

TEST(Annealer, RunKeepsEveryInvariantAndExactSums)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    AnnealOptions o = deterministic_options(40000);
    o.seed = 3;
    Annealer annealer(scene.z0, *scene.context, o);
    const AnnealResult r = annealer.run();
    const ValidationReport report = validate(from_model(r.model));
    EXPECT_TRUE(report.ok()) << report.message();
    EXPECT_EQ(report.genus, scene.surface_genus);
    // No commit adds a face turned against the surface, so only Z0's fold-overs (voxel faces whose
    // barycentre projects across a thin part) can remain, and the annealing replaces most of them.
    const size_t z0_fold_overs = count_fold_overs(from_model(scene.z0), *scene.context);
    EXPECT_LT(count_fold_overs(from_model(r.model), *scene.context), std::max<size_t>(z0_fold_overs, 1));
    EXPECT_GT(r.stats.rejections[static_cast<size_t>(Rejection::FoldOver)], 0u);
    EXPECT_TRUE(r.stats.energy_consistent);
    EXPECT_EQ(r.stats.proposals, 40000U);
    EXPECT_LE(r.stats.commits, r.stats.valid_proposals);
    EXPECT_LE(r.stats.valid_proposals, r.stats.proposals);
    uint64_t proposed = 0, accepted = 0;
    for (const OperatorCounts& c : r.stats.per_operator)
    {
        proposed += c.proposed;
        accepted += c.accepted;
    }
    EXPECT_EQ(proposed, r.stats.proposals);
    EXPECT_EQ(accepted, r.stats.commits);
    EXPECT_GT(r.stats.initial_temperature, r.stats.min_temperature);
    EXPECT_LE(r.best.total, r.end.total);
    // The energy the annealer reports is the energy of the model it returns.
    EXPECT_EQ(model_energy(r.model, *scene.context, o.energy, 392).sums, r.end.sums);
}

TEST(Annealer, ShortRunEndsWithoutFoldOversWhereZ0HasTheGenus)
{
    ZOME_REQUIRE_SHARED();
#ifdef ZOME_SANITIZED
    GTEST_SKIP() << "a quality figure, not a memory check: 10x slower under a sanitizer";
#endif
    // Fertility at 16 cells: the carved Z0 keeps the 4 handles but lies across thin parts in a few
    // places; a short run does not reach them all, so the repair after the schedule must. (After
    // 2·10^4 proposals a fold-over is still left in some seeds: engine README.)
    static const auto scene = test::make_anneal_scene("fertility.obj", 16);
    AnnealOptions o = deterministic_options(200000);
    o.target_nodes = 0;
    Annealer annealer(scene->z0, *scene->context, o);
    const AnnealResult r = annealer.run();
    EXPECT_GT(r.stats.fold_overs_before_repair, 0);
    EXPECT_EQ(r.stats.fold_overs_after_repair, 0);
    EXPECT_EQ(count_fold_overs(from_model(r.model), *scene->context), 0u);
    const ValidationReport report = validate(from_model(r.model));
    EXPECT_TRUE(report.ok()) << report.message();
    EXPECT_EQ(report.genus, scene->surface_genus);
}

TEST(Annealer, ProposalBudgetEndsWhenEverySeedOfASlabHasGone)
{
    ZOME_REQUIRE_SHARED();
    // The torus at 4 cells: ~50 balls in slabs of a few nodes each. A dead seed counts no
    // proposal, so once every node of the epoch's slab had been removed the epoch, and the run,
    // never ended (before the fix this seed stopped counting short of 3·10^5 proposals; 3 of 6
    // seeds at 10^6). A watchdog cancels a run still going after two minutes, so a regression
    // fails here instead of hanging the suite.
    static const auto scene = test::make_anneal_scene("torus.obj", 4);
    AnnealOptions o = deterministic_options(300000);
    o.seed = 5;
    o.target_nodes = 0;
    Annealer annealer(scene->z0, *scene->context, o);
    std::atomic<bool> done{false};
    std::thread watchdog([&] {
        for (int i = 0; i < 1200 && !done.load(); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        if (!done.load())
            annealer.cancel();
    });
    const AnnealResult r = annealer.run();
    done.store(true);
    watchdog.join();
    EXPECT_FALSE(r.stats.cancelled) << "the run did not end by itself: " << r.stats.proposals << " proposals";
    EXPECT_EQ(r.stats.proposals, 300000U);
    EXPECT_GT(r.stats.dead_seeds, 0U);
    EXPECT_TRUE(validate(from_model(r.model)).ok());
}

TEST(Annealer, OperatorWeightsDecideWhatIsProposed)
{
    ZOME_REQUIRE_SHARED();
    // Only MOVNODE and REMDIAG, 3 to 1: the workers draw with the options' weights.
    const test::AnnealScene& scene = bunny8();
    AnnealOptions o = deterministic_options(8000);
    o.operator_weights = {0, 0, 0, 1, 0, 3, 0};
    Annealer annealer(scene.z0, *scene.context, o);
    const AnnealResult r = annealer.run();
    for (int k = 0; k < kOperatorKinds; ++k)
    {
        const auto kind = static_cast<OperatorKind>(k);
        if (kind != OperatorKind::MovNode && kind != OperatorKind::RemDiag)
        {
            EXPECT_EQ(r.stats.per_operator[k].proposed, 0u) << operator_name(kind);
        }
    }
    const double movnode =
        static_cast<double>(r.stats.per_operator[static_cast<size_t>(OperatorKind::MovNode)].proposed);
    EXPECT_NEAR(movnode / static_cast<double>(r.stats.proposals), 0.75, 0.03);
    const ValidationReport report = validate(from_model(r.model));
    EXPECT_TRUE(report.ok()) << report.message();
}

TEST(Annealer, CancelInProgressStopsAndKeepsAValidBestModel)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    AnnealOptions o;
    o.threads = 1;
    o.seconds = 1e6; // only cancel ends this run
    o.progress_interval = 1e-3;
    Annealer annealer(scene.z0, *scene.context, o);
    int calls = 0;
    const AnnealResult r = annealer.run([&](const AnnealProgress& p) {
        ++calls;
        EXPECT_GE(p.temperature, 0.0);
        if (p.proposals > 2000)
            annealer.cancel();
    });
    EXPECT_TRUE(r.stats.cancelled);
    EXPECT_GE(calls, 2); // at least one during the run and the final one
    EXPECT_TRUE(validate(from_model(r.best_model)).ok());
    EXPECT_LE(r.best.total, r.start.total);
}

TEST(AnnealParallel, SnapshotsWhileThreadsRunAreValid)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    AnnealOptions o;
    o.threads = 2;
    o.seconds = 1e6;
    o.seed = 5;
    Annealer annealer(scene.z0, *scene.context, o);
    std::atomic<int> checked{0};
    std::atomic<bool> all_valid{true};
    std::thread observer([&] {
        while (checked.load() < 20)
        {
            if (annealer.progress().commits == 0)
            {
                std::this_thread::yield();
                continue;
            }
            const ZomeModel m = annealer.snapshot();
            if (!validate(from_model(m)).ok())
                all_valid.store(false);
            checked.fetch_add(1);
        }
        annealer.cancel();
    });
    const AnnealResult r = annealer.run();
    observer.join();
    EXPECT_TRUE(all_valid.load());
    EXPECT_TRUE(r.stats.energy_consistent);
    EXPECT_TRUE(validate(from_model(r.model)).ok());
}

TEST(AnnealParallel, ProposalBudgetIsSharedByTheThreads)
{
    ZOME_REQUIRE_SHARED();
    const test::AnnealScene& scene = bunny8();
    AnnealOptions o = deterministic_options(20000);
    o.threads = 4;
    Annealer annealer(scene.z0, *scene.context, o);
    const AnnealResult r = annealer.run();
    EXPECT_GE(r.stats.proposals, 20000U);
    EXPECT_LT(r.stats.proposals, 20000U + 4 * 64 + 64);
    EXPECT_TRUE(r.stats.energy_consistent);
    EXPECT_TRUE(validate(from_model(r.model)).ok());
}

} // namespace
} // namespace zomeify
