// "Fit my kits" before a run (core/pipeline/kit_fit_plan.h): the plan stays within the ball budget
// at the largest resolution that does, keeps the torus's hole, and says plainly when nothing fits.
#include "core/pipeline/kit_fit_plan.h"

#include <gtest/gtest.h>

#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/voxel/initial_model.h"
#include "tests/support/torus_surface.h"

using namespace zomeify;

namespace {

struct Torus : test::TorusSurface
{
    KitFitPlan plan(size_t budget, int max_resolution = 64) const
    {
        return plan_kit_fit(mesh, 1, is_inside(), probe_of(projector), budget, max_resolution);
    }
};

} // namespace

TEST(KitFitPlan, LargestResolutionWithinTheBudgetKeepingTheHole)
{
    const Torus t;
    const KitFitPlan plan = t.plan(150);
    ASSERT_TRUE(plan.possible) << plan.message;
    EXPECT_LE(plan.z0_nodes, 180u); // up to 20 % over: the target pulls the count down
    EXPECT_TRUE(plan.genus_kept);
    EXPECT_EQ(plan.target_nodes, std::min<size_t>(150, plan.z0_nodes));
    EXPECT_GT(plan.size_cm, 0.0);
    // One cell finer is over the budget, or loses the hole.
    const InitialModel finer = t.z0(plan.resolution + 1);
    EXPECT_TRUE(finer.model.nodes.size() > 180 || finer.report.topology.genus != 1);
    EXPECT_NE(plan.message.find("cells"), std::string::npos);
}

TEST(KitFitPlan, SizeAskedIsAnUpperBound)
{
    const Torus t;
    const KitFitPlan plan = t.plan(100000, 6);
    ASSERT_TRUE(plan.possible);
    EXPECT_LE(plan.resolution, 6);
    EXPECT_EQ(plan.target_nodes, plan.z0_nodes); // a coarse grid is not filled up to the budget
}

TEST(KitFitPlan, TooFewBallsSaysTheSmallestModel)
{
    const Torus t;
    const KitFitPlan plan = t.plan(5);
    EXPECT_FALSE(plan.possible);
    EXPECT_NE(plan.message.find("no size of this shape fits: the smallest model"), std::string::npos) << plan.message;
}
