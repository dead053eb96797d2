// The assembly sequence (core/build): every part in exactly one step, one piece after every step,
// deterministic, on a small hand-made model, the paper's bunny and the Z0 models of the shared meshes.
#include <filesystem>

#include <gtest/gtest.h>

#include "core/assembly/assembly_plan.h"
#include "core/assembly/plan_report.h"
#include "core/assembly/real_size.h"
#include "core/assembly/steps_html.h"
#include "core/base/errors.h"
#include "core/io/model_io.h"
#include "core/pipeline/pipeline.h"
#include "core/surface/prepare.h"
#include "core/surface/read_mesh.h"
#include "core/zome/slots.h"
#include "tests/support/paths.h"

namespace zomeify {
namespace {

//! A square of B0 struts with one diagonal (the planner reads the graph only; the diagonal is no
//! Zome strut, which plan_json would refuse).
ZomeModel tiny_model()
{
    ZomeModel m;
    const ZVec bx = zome_vector(vector_id(slot_of(ZVec{{0, 2, 0, 0, 0, 0}}), 0));
    const ZVec bz = zome_vector(vector_id(slot_of(ZVec{{0, 0, 0, 0, 0, 2}}), 0));
    m.nodes = {ZVec{}, bx, bx + bz, bz};
    m.struts = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}};
    return m;
}

void expect_valid(const ZomeModel& model, const BuildPlan& plan, const std::string& name)
{
    EXPECT_EQ(check_plan(model, plan), "") << name;
    EXPECT_EQ(plan.figures.steps, plan.steps.size()) << name;
    for (size_t s = 1; s < plan.steps.size(); ++s)
        EXPECT_FALSE(plan.steps[s].attach.empty()) << name << " step " << s + 1;
}

TEST(AssemblyPlan, TinyModelIsPlannedWholeAndInOrder)
{
    const ZomeModel m = tiny_model();
    const BuildPlan plan = plan_assembly(m);
    expect_valid(m, plan, "tiny");
    // Equal heights go by exact position: ball 3 (+z) before ball 1 (+x). The triangle 0-3-2 (6 parts)
    // closes the first step; ball 1 comes with its two struts.
    ASSERT_EQ(plan.steps.size(), 2u);
    EXPECT_EQ(plan.steps[0].balls, (std::vector<uint32_t>{0, 3, 2}));
    EXPECT_EQ(plan.steps[1].balls, (std::vector<uint32_t>{1}));
    EXPECT_EQ(plan.steps[1].attach, (std::vector<uint32_t>{0, 2}));
    EXPECT_EQ(plan.figures.two_strut_share, 1.0);
    EXPECT_EQ(plan.figures.max_dangling, 0u); // ball 3 hangs on one strut only within step 1
}

TEST(AssemblyPlan, BadModelsGiveOneLineErrors)
{
    EXPECT_THROW(plan_assembly(ZomeModel{}), InvalidInputError);
    ZomeModel two = tiny_model();
    two.struts = {{0, 1}, {2, 3}};
    EXPECT_THROW(plan_assembly(two), InvalidInputError);
    ZomeModel bad = tiny_model();
    bad.struts.push_back({0, 9});
    EXPECT_THROW(plan_assembly(bad), InvalidInputError);
    EXPECT_THROW(parse_up_axis("w"), InvalidInputError);
    EXPECT_EQ(parse_up_axis("-z").axis, 2);
    EXPECT_EQ(parse_up_axis("-z").sign, -1);
}

TEST(AssemblyPlan, CheckPlanFindsFaults)
{
    const ZomeModel m = tiny_model();
    BuildPlan plan = plan_assembly(m);
    plan.steps[0].struts.pop_back();
    EXPECT_NE(check_plan(m, plan), "");
}

TEST(AssemblyPlan, PaperBunnyBothOrders)
{
    ZOME_REQUIRE_SHARED();
    const std::string path = test::shared_path("data/vef/bunny.vef");
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << "no " << path;
    const ZomeModel m = read_model_file(path);
    const BuildPlan plan = plan_assembly(m);
    expect_valid(m, plan, "bunny");
    expect_valid(m, plan_breadth_first(m), "bunny naive");
    EXPECT_EQ(plan_json(m, plan, plan.figures), plan_json(m, plan_assembly(m), plan.figures)); // deterministic
    for (const BuildStep& s : plan.steps)
        EXPECT_LE(s.balls.size() + s.struts.size(), 14u);
    // Renumbered balls and turned struts (as a share link may give) make the same steps in positions.
    ZomeModel renumbered = m;
    const size_t n = m.nodes.size();
    for (size_t i = 0; i < n; ++i)
        renumbered.nodes[i] = m.nodes[n - 1 - i];
    for (auto& st : renumbered.struts)
        st = {static_cast<uint32_t>(n - 1 - st[1]), static_cast<uint32_t>(n - 1 - st[0])};
    const BuildPlan again = plan_assembly(renumbered);
    ASSERT_EQ(again.steps.size(), plan.steps.size());
    for (size_t s = 0; s < plan.steps.size(); ++s)
        for (size_t i = 0; i < plan.steps[s].balls.size(); ++i)
            EXPECT_EQ(renumbered.nodes.at(again.steps[s].balls.at(i)), m.nodes[plan.steps[s].balls[i]]);
    // Another pose is another plan, still whole.
    PlanOptions side;
    side.up = parse_up_axis("-x");
    expect_valid(m, plan_assembly(m, side), "bunny -x");
    const std::string html = steps_html(m, plan, "bunny <vef>");
    EXPECT_NE(html.find("Step " + std::to_string(plan.steps.size()) + " of"), std::string::npos);
    EXPECT_EQ(html.find("http://"), html.find("http://www.w3.org/2000/svg")); // the SVG namespace only
    EXPECT_NE(html.find("bunny &lt;vef&gt;"), std::string::npos);
}

TEST(AssemblyPlan, SharedMeshesInitialModels)
{
    ZOME_REQUIRE_SHARED();
    const char* meshes[] = {"3holes",    "bunny",     "cube",     "eight",  "elk",
                            "fertility", "rockerarm", "scorpion", "sphere", "torus"};
    for (const char* name : meshes)
    {
        const std::string path = test::shared_path(std::string("data/meshes/") + name + ".obj");
        if (!std::filesystem::exists(path))
        {
            std::cout << "skipping " << name << ": no " << path << "\n";
            continue;
        }
        const PreparedSurface surface = prepare_surface(read_mesh_file(path));
        PipelineOptions options;
        options.resolution = 8;
        options.initial_only = true;
        options.advise = false;
        options.fidelity_samples = 0;
        const ZomeModel m = run_pipeline(surface.mesh, surface.report.genus, options).model;
        expect_valid(m, plan_assembly(m), name);
        expect_valid(m, plan_breadth_first(m), std::string(name) + " naive");
    }
}

TEST(RealSize, SizeToScaleAndBack)
{
    // 50 cm over a mesh 10 units long: (500 - 17.673) mm / 74.86 mm = 6.44 b1 spans, less the cell Z0 adds.
    const double b1 = b1_for_size_cm(10.0, 50.0);
    EXPECT_NEAR(10.0 / b1, (500.0 - 17.673) / 74.862 - 1.0, 1e-3);
    EXPECT_NEAR(built_size_cm(0.0), 1.7673, 1e-4);
    EXPECT_THROW(b1_for_size_cm(10.0, 5.0), InvalidInputError);
    EXPECT_THROW(b1_for_size_cm(0.0, 50.0), InvalidInputError);
    EXPECT_THROW(b1_for_size_cm(10.0, 1e9), InvalidInputError);
}

} // namespace
} // namespace zomeify
