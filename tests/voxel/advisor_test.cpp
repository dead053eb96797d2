// The resolution advisor: at its resolution, Z0 keeps the genus of every shared mesh; and its
// message for a user whose choice loses handles.

#include <gtest/gtest.h>

#include "core/voxel/advisor.h"
#include "tests/support/paths.h"
#include "tests/voxel/voxel_test_support.h"

using namespace zomeify;
using namespace zomeify::voxel_test;

TEST(VoxelAdvisor, GenusKeptAtTheAdvisedResolutionForEverySharedMesh)
{
    ZOME_REQUIRE_SHARED();
    for (const auto& name : shared_mesh_names())
    {
        SCOPED_TRACE(name);
        const LoadedSurface& s = shared_surface(name);
        // The scan is bounded by max_resolution here, not by wall time: sanitizer and wasm builds
        // are slower, and the answer must not depend on the machine.
        AdvisorOptions unbounded;
        unbounded.seconds = 1e9;
        const AdvisorResult advice = advise_resolution(s.mesh, s.genus, s.predicate(), unbounded);
        ASSERT_TRUE(advice.found);
        ASSERT_FALSE(advice.trials.empty());
        EXPECT_EQ(advice.trials.back().resolution, advice.resolution);
        for (size_t i = 0; i + 1 < advice.trials.size(); ++i)
            EXPECT_FALSE(advice.trials[i].valid && advice.trials[i].genus == s.genus);

        InitialModelOptions options;
        options.resolution = advice.resolution;
        options.target_genus = s.genus;
        const InitialModel z0 = build_initial_model(s.mesh, s.predicate(), options);
        EXPECT_TRUE(z0.report.valid);
        EXPECT_EQ(z0.report.topology.genus, s.genus);
        EXPECT_EQ(model_genus(z0.model), s.genus);
        EXPECT_EQ(closed_manifold_problem(z0.model), "");
        long long halfedge_genus = -1;
        EXPECT_EQ(halfedge_problem(z0.model, &halfedge_genus), "");
        EXPECT_EQ(halfedge_genus, s.genus);
        EXPECT_EQ(lattice_problem(z0.model), "");
        std::cout << name << ": genus " << s.genus << " kept from " << advice.resolution << " cells ("
                  << advice.trials.size() << " resolutions scanned in " << advice.seconds << " s)\n";
    }
}

TEST(VoxelAdvisor, Message)
{
    AdvisorResult advice;
    advice.found = true;
    advice.resolution = 14;
    advice.surface_genus = 4;
    EXPECT_EQ(advice_message(10, 0, advice), "at 10 cells the 4 handles of this shape close up; 14 keeps them");
    EXPECT_EQ(advice_message(10, 3, advice), "at 10 cells 1 of the 4 handles of this shape closes up; 14 keeps them");
    EXPECT_EQ(advice_message(10, 6, advice),
              "at 10 cells the model has 2 handles more than this shape (parts that nearly touch merge); "
              "14 keeps them");
    advice.surface_genus = 1;
    EXPECT_EQ(advice_message(8, 0, advice), "at 8 cells the handle of this shape closes up; 14 keeps it");
    advice.found = false;
    advice.trials = {{4, true, 0, 0.0}, {64, true, 0, 0.0}};
    EXPECT_EQ(advice_message(8, 0, advice),
              "at 8 cells the handle of this shape closes up; no resolution up to 64 keeps the genus (genus 1)");
}
