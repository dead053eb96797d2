// The automatic resolution: on every shared mesh, the coarsest grid that keeps the genus with at
// least min_balls balls (every coarser grid fails one of the two), and a plain message.

#include <gtest/gtest.h>

#include "core/voxel/auto_resolution.h"
#include "tests/support/paths.h"
#include "tests/voxel/voxel_test_support.h"

using namespace zomeify;
using namespace zomeify::voxel_test;

TEST(AutoResolution, CoarsestGridKeepingTheGenusWithEnoughBallsOnEverySharedMesh)
{
    ZOME_REQUIRE_SHARED();
    for (const auto& name : shared_mesh_names())
    {
        SCOPED_TRACE(name);
        const LoadedSurface& s = shared_surface(name);
        AutoResolutionOptions options;
        options.seconds = 1e9; // bounded by max_resolution, so the answer does not depend on the machine
        options.initial.surface_probe = probe_of(*s.projector); // as a run does
        const AutoResolution a = choose_resolution(s.mesh, s.genus, s.predicate(), options);
        ASSERT_TRUE(a.genus_kept) << a.message; // every shared mesh keeps its genus below 64 cells
        EXPECT_GE(a.balls, options.min_balls);
        EXPECT_EQ(a.genus, s.genus);
        EXPECT_EQ(a.searched_to, a.resolution);
        ASSERT_FALSE(a.trials.empty());
        EXPECT_EQ(a.trials.front().resolution, options.min_resolution);
        EXPECT_EQ(a.trials.back().resolution, a.resolution);

        // Z0 at the chosen grid is what the run will start from: enough balls, the genus kept.
        InitialModelOptions z0_options = options.initial;
        z0_options.resolution = a.resolution;
        z0_options.target_genus = s.genus;
        const InitialModel z0 = build_initial_model(s.mesh, s.predicate(), z0_options);
        EXPECT_EQ(z0.model.nodes.size(), a.balls);
        EXPECT_TRUE(z0.report.valid);
        EXPECT_EQ(z0.report.topology.genus, s.genus);

        // The grid just below fails the rule.
        if (a.resolution > options.min_resolution)
        {
            z0_options.resolution = a.resolution - 1;
            const InitialModel below = build_initial_model(s.mesh, s.predicate(), z0_options);
            const bool kept = below.report.valid && below.report.topology.genus == s.genus;
            EXPECT_FALSE(kept && below.model.nodes.size() >= options.min_balls);
        }
        EXPECT_NE(a.message.find(std::to_string(a.resolution) + " cells"), std::string::npos) << a.message;
        std::cout << name << ": " << a.message << " (" << a.seconds << " s)\n";
    }
}

TEST(AutoResolution, SaysSoWhenNoGridKeepsTheGenus)
{
    ZOME_REQUIRE_SHARED();
    // Asking a genus-0 sphere for genus 1: no grid keeps it; the coarsest grid with enough balls
    // is taken and the message names the search.
    const LoadedSurface& s = shared_surface("sphere");
    AutoResolutionOptions options;
    options.max_resolution = 20;
    options.seconds = 1e9;
    const AutoResolution a = choose_resolution(s.mesh, 1, s.predicate(), options);
    EXPECT_FALSE(a.genus_kept);
    EXPECT_EQ(a.searched_to, 20);
    EXPECT_GE(a.balls, options.min_balls);
    EXPECT_LT(a.resolution, 20);
    EXPECT_NE(a.message.find("no grid up to 20 cells keeps the hole through it"), std::string::npos) << a.message;
}
