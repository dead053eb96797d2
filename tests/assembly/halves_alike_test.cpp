// Build steps of a mirror-symmetric model (issue 41, item 3): both halves built alike, every step its
// own mirror image about the model's plane, still one piece after each step and as well braced as the
// plain order; asymmetric models and planes the planner cannot pair on are refused.
#include <algorithm>

#include <gtest/gtest.h>

#include "core/assembly/assembly_plan.h"
#include "core/assembly/plan_report.h"
#include "core/assembly/steps_html.h"
#include "core/base/errors.h"
#include "core/pipeline/pipeline.h"
#include "core/zome/slots.h"
#include "tests/support/generated_shapes.h"

namespace zomeify {
namespace {

//! The car's symmetric initial model (plane z = 0 of the mesh; length along x, up along y).
const ZomeModel& symmetric_car()
{
    static const ZomeModel model = [] {
        const test::GeneratedShape car = test::make_car();
        PipelineOptions o;
        o.resolution = 9;
        o.mirror = MirrorMode::Auto;
        o.initial_only = true;
        o.advise = false;
        o.fidelity_samples = 0;
        return run_pipeline(car.mesh, car.genus, o).model;
    }();
    return model;
}

TEST(HalvesAlike, EveryStepOfASymmetricModelIsItsOwnMirrorImage)
{
    const ZomeModel& car = symmetric_car();
    const std::optional<LatticeMirror> plane = building_mirror(car, parse_up_axis("y"));
    ASSERT_TRUE(plane.has_value());
    EXPECT_EQ(plane->axis, 2); // the car's plane, across z; y is up
    PlanOptions options;
    options.mirror = plane;
    const BuildPlan paired = plan_assembly(car, options);
    ASSERT_TRUE(paired.mirror.has_value());
    EXPECT_EQ(check_plan(car, paired), ""); // every ball and strut once, one piece, steps symmetric
    const std::vector<uint32_t> image = *mirror_ball_images(car, *plane);
    size_t off_plane = 0;
    for (const BuildStep& step : paired.steps)
        for (uint32_t v : step.balls)
        {
            EXPECT_NE(std::find(step.balls.begin(), step.balls.end(), image[v]), step.balls.end());
            off_plane += image[v] != v;
        }
    EXPECT_GT(off_plane, car.nodes.size() / 2);
    // As well braced as the plain order, within a step's worth.
    const BuildPlan plain = plan_assembly(car);
    EXPECT_GE(paired.figures.two_strut_share, plain.figures.two_strut_share - 0.05);
    EXPECT_LE(paired.figures.max_overhang_b0, plain.figures.max_overhang_b0 + 1.0);
    EXPECT_LE(paired.figures.max_dangling, plain.figures.max_dangling + 2);
    // The reports say so.
    EXPECT_NE(plan_text(car, paired, plain.figures).find("Both halves are built alike"), std::string::npos);
    EXPECT_NE(plan_json(car, paired, plain.figures).find("\"mirror\":{\"axis\":\"z\""), std::string::npos);
    EXPECT_NE(steps_html(car, paired, "car").find("mirror images about the plane across the z axis"),
              std::string::npos);
    EXPECT_EQ(plan_text(car, plain, plain.figures).find("Both halves"), std::string::npos);
}

TEST(HalvesAlike, CheckPlanFindsABallBuiltApartFromItsImage)
{
    const ZomeModel& car = symmetric_car();
    PlanOptions options;
    options.mirror = building_mirror(car, options.up);
    BuildPlan plan = plan_assembly(car, options);
    ASSERT_EQ(check_plan(car, plan), "");
    // Splitting off a step's last ball (placed last, so nothing in its step hangs on it) with its struts
    // keeps the plan whole and one piece: only the pairing breaks.
    const std::vector<uint32_t> image = *mirror_ball_images(car, *plan.mirror);
    size_t s = plan.steps.size();
    while (s > 0 && image[plan.steps[s - 1].balls.back()] == plan.steps[s - 1].balls.back())
        --s;
    ASSERT_GT(s, 0u) << "no step ends with a ball off the plane";
    BuildStep& step = plan.steps[s - 1];
    const uint32_t v = step.balls.back();
    BuildStep apart;
    apart.balls = {v};
    for (auto it = step.struts.begin(); it != step.struts.end();)
        if (car.struts[*it][0] == v || car.struts[*it][1] == v)
        {
            apart.struts.push_back(*it);
            const uint32_t other = car.struts[*it][0] == v ? car.struts[*it][1] : car.struts[*it][0];
            apart.attach.push_back(other);
            it = step.struts.erase(it);
        }
        else
            ++it;
    step.balls.pop_back();
    plan.steps.insert(plan.steps.begin() + static_cast<std::ptrdiff_t>(s), apart);
    EXPECT_NE(check_plan(car, plan).find("mirror image"), std::string::npos) << check_plan(car, plan);
}

TEST(HalvesAlike, OnlyAPlaneTheModelMapsOntoAcrossAnotherAxisThanUp)
{
    const ZomeModel& car = symmetric_car();
    PlanOptions across_up;
    across_up.up = parse_up_axis("z"); // the plane's own axis
    EXPECT_FALSE(building_mirror(car, across_up.up).has_value() &&
                 building_mirror(car, across_up.up)->axis == across_up.up.axis);
    across_up.mirror = LatticeMirror{2, building_mirror(car, parse_up_axis("y"))->sum};
    EXPECT_THROW(plan_assembly(car, across_up), InvalidInputError);
    PlanOptions wrong;
    wrong.mirror = LatticeMirror{0, building_mirror(car, parse_up_axis("y"))->sum}; // the car is long along x
    EXPECT_THROW(plan_assembly(car, wrong), InvalidInputError);
    // A lopsided model: one ball more on one side (beyond the farthest ball along x of the top z layer,
    // so a new place) has no plane to build alike, and the planner says so.
    ZomeModel lopsided = car;
    uint32_t top = 0;
    for (uint32_t v = 0; v < car.nodes.size(); ++v)
    {
        const double z = car.nodes[v].coord(2), zt = car.nodes[top].coord(2);
        if (z > zt || (z == zt && car.nodes[v].coord(0) > car.nodes[top].coord(0)))
            top = v;
    }
    lopsided.nodes.push_back(car.nodes[top] + zome_vector(vector_id(slot_of(ZVec{{0, 2, 0, 0, 0, 0}}), 0)));
    lopsided.struts.push_back({top, static_cast<uint32_t>(lopsided.nodes.size() - 1)});
    EXPECT_FALSE(building_mirror(lopsided, parse_up_axis("y")).has_value());
    PlanOptions stale;
    stale.mirror = building_mirror(car, stale.up);
    EXPECT_THROW(plan_assembly(lopsided, stale), InvalidInputError);
}

} // namespace
} // namespace zomeify
