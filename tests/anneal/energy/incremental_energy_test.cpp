// Incremental energy (design §3.3): for many random local edits on the closed fixtures, the ΔE
// simulated from the change alone equals the change of a full recomputation, and after each commit
// the state's sums equal those of a fresh evaluate_energy, bit for bit.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "core/anneal/energy/energy_state.h"
#include "core/mesh/model_convert.h"
#include "core/mesh/validate.h"
#include "tests/anneal/energy/energy_edits.h"
#include "tests/anneal/energy/energy_test_support.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify {
namespace {

using Rng = test::EditRng;
using test::Edit;
using test::move_node;
using test::random_edit;

ValidateOptions topology_only()
{
    ValidateOptions o;
    o.check_zome = false; // the energy does not care whether the edges are Zome vectors
    return o;
}

// The local terms (paper §4): E_surface, which needs the faces' handles at commit, is checked with
// the operators (OperatorEnergy.SurfaceTerm…).
EnergyOptions options_for(const ZomeModel& model)
{
    EnergyOptions o = paper_energy();
    o.target_nodes = model.nodes.size() + 3;
    return o;
}

// A closed fixture as a mesh with its energy state, for random edits.
struct FixtureEnergy
{
    explicit FixtureEnergy(const ZomeModel& model)
        : mesh(from_model(model)), scene(test::sphere_scene_for(model, test::energy_test_transform())),
          options(options_for(model)), state(mesh, *scene.context, options)
    {
    }
    ZomeMesh mesh;
    test::EnergyScene scene;
    EnergyOptions options;
    EnergyState state;
};

TEST(EnergyIncremental, DeltaEqualsFullRecomputationOnRandomEdits)
{
    constexpr int kEditsPerModel = 300;
    std::map<std::string, int> counts;
    for (const fixtures::NamedModel& named : fixtures::closed_models())
    {
        SCOPED_TRACE(named.name);
        FixtureEnergy fixture(named.model);
        auto& [mesh, scene, options, state] = fixture;
        Rng rng(12345);
        for (int step = 0; step < kEditsPerModel; ++step)
        {
            std::optional<Edit> edit = random_edit(mesh, rng);
            ASSERT_TRUE(edit.has_value());
            SCOPED_TRACE(::testing::Message() << "step " << step << " " << edit->kind);
            ASSERT_EQ(check_change(mesh, edit->change), "");
            const EnergyTerms before = evaluate_energy(mesh, *scene.context, options);
            const EnergyDelta delta = state.simulate(mesh, edit->change);
            ASSERT_TRUE(delta.ok());
            const double de = state.delta_energy(delta);

            edit->apply(mesh);
            const ValidationReport report = validate(mesh, topology_only());
            ASSERT_TRUE(report.ok()) << report.message();
            ASSERT_EQ(report.genus, named.genus);
            const EnergyTerms after = evaluate_energy(mesh, *scene.context, options);

            EXPECT_TRUE(before.sums + delta.sums == after.sums);
            const double de_full = energy_change(before.sums, after.sums - before.sums, options);
            EXPECT_NEAR(de, de_full, 1e-9 * std::max(std::abs(de_full), 1e-12));
            EXPECT_NEAR(de, after.total - before.total, 1e-12 * std::max(1.0, std::abs(after.total)));
            ASSERT_TRUE(state.commit(delta));
            ASSERT_TRUE(state.sums() == after.sums);
            EXPECT_DOUBLE_EQ(state.energy(), after.total);
            ++counts[edit->kind];
        }
    }
    for (const auto& [kind, n] : counts)
    {
        EXPECT_GT(n, 20) << kind;
    }
}

// FoldOvers::Refuse stops at an added fold-over face (the annealer refuses those changes); every
// other change gets the very sums FoldOvers::Count computes.
TEST(EnergyIncremental, RefusingFoldOversStopsExactlyAtTheChangesThatAddOne)
{
    int with_fold_over = 0, without = 0;
    for (const fixtures::NamedModel& named : fixtures::closed_models())
    {
        SCOPED_TRACE(named.name);
        FixtureEnergy fixture(named.model);
        auto& [mesh, scene, options, state] = fixture;
        Rng rng(777);
        for (int step = 0; step < 300; ++step)
        {
            std::optional<Edit> edit = random_edit(mesh, rng);
            ASSERT_TRUE(edit.has_value());
            const EnergyDelta counted = state.simulate(mesh, edit->change, FoldOvers::Count);
            const EnergyDelta refused = state.simulate(mesh, edit->change, FoldOvers::Refuse);
            ASSERT_TRUE(counted.ok());
            EXPECT_EQ(refused.adds_fold_over, counted.adds_fold_over);
            if (counted.adds_fold_over)
            {
                EXPECT_EQ(refused.status, ChangeStatus::FoldOver);
                ++with_fold_over;
            }
            else
            {
                EXPECT_TRUE(refused.ok());
                EXPECT_TRUE(refused.sums == counted.sums);
                ++without;
            }
            edit->apply(mesh);
            ASSERT_TRUE(state.commit(counted));
        }
    }
    EXPECT_GT(with_fold_over, 20);
    EXPECT_GT(without, 20);
}

TEST(EnergyIncremental, SimulateDoesNotDependOnTheOrderOfTheDescription)
{
    // A node move described with its lists reversed gives the same integers.
    const ZomeModel model = fixtures::cube_shell(3);
    const ZomeMesh mesh = from_model(model);
    const test::EnergyScene scene = test::sphere_scene_for(model, test::energy_test_transform());
    const EnergyOptions options = options_for(model);
    Rng rng(7);
    int compared = 0;
    while (compared < 20)
    {
        std::optional<Edit> e = move_node(mesh, rng);
        if (!e)
        {
            continue;
        }
        LocalChange reversed;
        const LocalChange& c = e->change;
        for (size_t i = c.removed_faces().size(); i-- > 0;)
        {
            reversed.remove_face(c.removed_faces()[i]);
        }
        for (size_t i = c.removed_struts().size(); i-- > 0;)
        {
            reversed.remove_strut(c.removed_struts()[i]);
        }
        reversed.remove_node(c.removed_nodes()[0]);
        reversed.add_node(c.added_nodes()[0]);
        for (size_t i = c.added_struts().size(); i-- > 0;)
        {
            reversed.add_strut(c.added_struts()[i].b, c.added_struts()[i].a);
        }
        for (size_t i = c.added_faces().size(); i-- > 0;)
        {
            // Same face, starting at another corner.
            const NewFace& f = c.added_faces()[i];
            std::vector<ZVec> rotated(f.view().begin() + 1, f.view().end());
            rotated.push_back(f.corners[0]);
            reversed.add_face(rotated);
        }
        const EnergyDelta a = simulate_change(mesh, c, *scene.context, options);
        const EnergyDelta b = simulate_change(mesh, reversed, *scene.context, options);
        ASSERT_TRUE(a.ok());
        EXPECT_TRUE(a.sums == b.sums);
        ++compared;
    }
}

TEST(EnergyIncremental, ConcurrentSimulationsAgreeWithSerialOnes)
{
    const ZomeModel model = fixtures::cube_shell(3);
    const ZomeMesh mesh = from_model(model);
    const test::EnergyScene scene = test::sphere_scene_for(model, test::energy_test_transform());
    const EnergyOptions options = options_for(model);
    Rng rng(99);
    std::vector<Edit> edits;
    while (edits.size() < 200)
    {
        if (std::optional<Edit> e = random_edit(mesh, rng))
        {
            edits.push_back(std::move(*e));
        }
    }
    std::vector<EnergySums> serial;
    for (const Edit& e : edits)
    {
        serial.push_back(simulate_change(mesh, e.change, *scene.context, options).sums);
    }
    scene.context->clear_cache(); // the threads fill the cache concurrently
    std::vector<std::vector<EnergySums>> results(3);
    std::vector<std::thread> threads;
    for (size_t t = 0; t < results.size(); ++t)
    {
        threads.emplace_back([&, t] {
            for (const Edit& e : edits)
            {
                results[t].push_back(simulate_change(mesh, e.change, *scene.context, options).sums);
            }
        });
    }
    for (std::thread& th : threads)
    {
        th.join();
    }
    for (const auto& r : results)
    {
        ASSERT_EQ(r.size(), serial.size());
        for (size_t i = 0; i < r.size(); ++i)
        {
            EXPECT_TRUE(r[i] == serial[i]) << "edit " << i;
        }
    }
}

TEST(EnergyIncremental, InconsistentDescriptionsAreReported)
{
    const ZomeModel model = fixtures::cube_shell(1);
    const ZomeMesh mesh = from_model(model);
    const test::EnergyScene scene = test::sphere_scene_for(model, test::energy_test_transform());
    const EnergyOptions options = options_for(model);

    // A strut to a node that is neither new nor on the removed region.
    LocalChange c;
    c.add_strut(mesh.position(Vertex(0)), mesh.position(Vertex(7)));
    EXPECT_EQ(simulate_change(mesh, c, *scene.context, options).status, ChangeStatus::UnknownNode);
    EXPECT_NE(check_change(mesh, c), "");

    // A removed node whose struts are kept.
    c.clear();
    c.remove_node(Vertex(0));
    EXPECT_EQ(simulate_change(mesh, c, *scene.context, options).status, ChangeStatus::KeptStrutToRemovedNode);
    EXPECT_NE(check_change(mesh, c), "");

    // Faces must be triangles or quads; a full list refuses and is reported.
    c.clear();
    const std::vector<ZVec> pentagon(5);
    EXPECT_FALSE(c.add_face(pentagon));
    EXPECT_EQ(simulate_change(mesh, c, *scene.context, options).status, ChangeStatus::Overflow);
    c.clear();
    for (size_t i = 0; i < LocalChange::kMaxNodes; ++i)
    {
        EXPECT_TRUE(c.add_node(ZVec{}));
    }
    EXPECT_FALSE(c.add_node(ZVec{}));
    EXPECT_TRUE(c.overflowed());
    EnergyState state(mesh, *scene.context, options);
    const EnergySums before = state.sums();
    const EnergyDelta bad = state.simulate(mesh, c);
    EXPECT_FALSE(bad.ok());
    EXPECT_EQ(state.delta_energy(bad), 0.0);
    EXPECT_FALSE(state.commit(bad));
    EXPECT_TRUE(state.sums() == before);
}

} // namespace
} // namespace zomeify
