// For every operator kind, the incremental ΔE of a proposal (EnergyState::simulate +
// delta_energy) equals a full recomputation of the energy after apply_proposal(), and after
// EnergyState::commit the state's sums equal a fresh evaluation (reset()) bit for bit. On Z0 of
// the shared torus, with the real surface context. Proposals/s per kind: tests/bench/bench_operators.
#include <array>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/anneal/energy/energy_state.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "tests/anneal/operators/operator_test_support.h"
#include "tests/support/paths.h"

namespace zomeify {
namespace {

// Every step is checked against two full recomputations; under a sanitizer (10x slower) fewer
// steps per kind still reach every operator.
#ifdef ZOME_SANITIZED
constexpr int kMinPerKind = 10;
#else
constexpr int kMinPerKind = 25;
#endif

EnergyOptions options_for(size_t nodes)
{
    EnergyOptions o;
    o.target_nodes = nodes;
    return o;
}

// Applies random proposals of every kind, checking each against a full recomputation.
void check_every_kind(double w_surface)
{
    const test::SharedScene scene = test::shared_scene("torus.obj", 10);
    ZomeMesh mesh = from_model(scene.z0);
    EnergyOptions options = options_for(mesh.n_vertices());
    options.w_surface = w_surface;
    EnergyState state(mesh, *scene.context, options);
    EnergyTerms before = evaluate_energy(mesh, *scene.context, options);
    std::array<int, kOperatorKinds> checked{};
    Rng rng(20261123);
    Proposal p;
    for (long step = 0; step < 400000; ++step)
    {
        if (*std::min_element(checked.begin(), checked.end()) >= kMinPerKind)
            break;
        const auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
        if (!test::propose_at(kind, mesh, test::random_node(mesh, rng), rng, p))
            continue;
        SCOPED_TRACE(::testing::Message() << "step " << step << " " << operator_name(kind));
        ASSERT_EQ(check_change(mesh, p.change), "");
        EnergyDelta delta = state.simulate(mesh, p.change);
        ASSERT_TRUE(delta.ok());
        state.add_surface_change(mesh, p.change, delta);
        const double de = state.delta_energy(delta);
        FixedList<Face, LocalChange::kMaxFaces> added;
        apply_proposal(mesh, p, &added);
        const ValidationReport report = validate(mesh);
        ASSERT_TRUE(report.ok()) << report.message();
        ASSERT_EQ(report.genus, 1);
        const EnergyTerms after = evaluate_energy(mesh, *scene.context, options);
        EXPECT_TRUE(before.sums + delta.sums == after.sums);
        const double de_full = after.total - before.total;
        EXPECT_LE(std::abs(de - de_full), 1e-9 * std::max(std::abs(de_full), 1e-9))
            << "incremental " << de << " full " << de_full;
        ASSERT_TRUE(state.commit(delta, std::span<const Face>(added.begin(), added.size())));
        EnergyState fresh(mesh, *scene.context, options);
        ASSERT_TRUE(state.sums() == fresh.sums());
        before = after;
        ++checked[static_cast<size_t>(kind)];
    }
    for (int k = 0; k < kOperatorKinds; ++k)
        EXPECT_GE(checked[static_cast<size_t>(k)], kMinPerKind) << operator_name(static_cast<OperatorKind>(k));
}

TEST(OperatorEnergy, IncrementalDeltaEqualsFullRecomputationForEveryKind) { check_every_kind(0.0); }

// The same with E_surface (the surface's distance to the model), whose change reads the faces
// near the change through a grid and the points' nearest faces.
TEST(OperatorEnergy, SurfaceTermIncrementalEqualsFullRecomputationForEveryKind)
{
    ZOME_REQUIRE_SHARED();
    check_every_kind(10.0);
}

} // namespace
} // namespace zomeify
