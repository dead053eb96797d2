// The resolution advisor: at its resolution, Z0 keeps the genus of every shared mesh; and its
// message for a user whose choice loses handles.

#include <gtest/gtest.h>

#include "core/pipeline/z0_choice.h"
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
        // The scan is bounded by max_resolution, never by wall time: the answer does not depend on the machine.
        const AdvisorResult advice = advise_resolution(s.mesh, s.genus, s.predicate());
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
    EXPECT_EQ(advice_message(8, 0, advice, 4, 32),
              "at 8 cells the handle of this shape closes up; no grid from 4 to 32 cells keeps it");
}

TEST(VoxelAdvisor, HintIsTheNearestGridThatKeepsTheGenusAndTrue)
{
    // The knotted tube at a grid where its strands merge: the hint names the nearest grid that keeps
    // the genus (finer first at an equal distance), and every nearer grid misses it.
    const LoadedSurface& s = generated_surface("trefoil");
    const auto z0_at = [&](int n) {
        return build_initial_model(s.mesh, s.predicate(), run_z0_options(*s.projector, s.genus, n, 0.0));
    };
    const auto kept = [&](int n) {
        const InitialModel m = z0_at(n);
        return m.report.valid && m.report.topology.genus == s.genus;
    };
    for (int resolution = 9; resolution <= 16; ++resolution)
    {
        const InitialModel z0 = z0_at(resolution);
        if (!z0.report.valid || z0.report.topology.genus == s.genus)
            continue;
        SCOPED_TRACE(resolution);
        const GenusAdvice hint = genus_advice(s.mesh, s.genus, s.predicate(), resolution, z0.report.topology.genus,
                                              run_z0_options(*s.projector, s.genus, resolution, 0.0));
        ASSERT_GT(hint.resolution, 0) << hint.message;
        EXPECT_NE(hint.message.find("; " + std::to_string(hint.resolution) + " keeps it"), std::string::npos)
            << hint.message;
        EXPECT_TRUE(kept(hint.resolution));
        const int d = std::abs(hint.resolution - resolution);
        for (int n = resolution - d + 1; n < resolution + d; ++n)
        {
            if (n != resolution)
            {
                EXPECT_FALSE(kept(n)) << n;
            }
        }
        if (hint.resolution < resolution)
        {
            EXPECT_FALSE(kept(resolution + d)) << "the finer grid at the same distance";
        }
        std::cout << "trefoil: " << hint.message << "\n";
        return; // one grid that loses the genus is enough
    }
    ADD_FAILURE() << "no grid from 9 to 16 cells loses the knotted tube's genus: the shape no longer tests the hint";
}
