// The annealer's clearance rule (clearance_index.h): a crafted change of each clash kind against a
// B1 cube is refused with that kind, and random operator proposals are refused exactly when
// applying them would leave parts closer than the rules allow (checked by brute force).
#include <gtest/gtest.h>

#include "core/anneal/proposal.h"
#include "core/anneal/rules/clearance_index.h"
#include "core/geom/clearance.h"
#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"
#include "core/mesh/model_convert.h"
#include "core/zome/clearance_rules.h"
#include "tests/anneal/operators/operator_test_support.h"
#include "tests/support/paths.h"
#include "tests/support/zome_fixtures.h"

namespace zomeify {
namespace {

// A point from twice its coordinates, each as (φ-coefficient, integer).
ZVec at(int xa, int xb, int ya, int yb, int za, int zb) { return ZVec{{xa, xb, ya, yb, za, zb}}; }

Box3 domain() { return dilated(Box3{Vec3::Constant(-1.0), Vec3::Constant(3.0)}, 2.0); }

ClashKind check_on_cube(const LocalChange& change)
{
    const ZomeMesh cube = from_model(fixtures::cube_shell(1)); // corners at 0 and φ on each axis
    ClearanceIndex index(domain());
    index.reset(cube);
    return index.check(change);
}

TEST(ClearanceIndex, ABallTooCloseToAnotherIsRefused)
{
    LocalChange c;
    c.add_node(at(1, -1, 0, 0, 0, 0)); // (0.309, 0, 0): 0.309 b0 from the corner at the origin
    EXPECT_EQ(check_on_cube(c), ClashKind::BallBall);
}

TEST(ClearanceIndex, ABallOnAStrutItDoesNotHoldIsRefused)
{
    LocalChange c;
    c.add_node(at(1, 0, -1, 2, 0, 0)); // (φ/2, 0.191, 0): 0.191 b0 from the edge along x
    EXPECT_EQ(check_on_cube(c), ClashKind::BallStrut);
}

TEST(ClearanceIndex, StrutsPassingCloseAreRefused)
{
    // A B1 strut along z at (φ/2, 0.118): 0.118 b0 from the cube's edge along x, ends far away.
    LocalChange c;
    const ZVec a = at(1, 0, 2, -3, -1, 0), b = at(1, 0, 2, -3, 1, 0);
    c.add_node(a);
    c.add_node(b);
    c.add_strut(a, b);
    EXPECT_EQ(check_on_cube(c), ClashKind::StrutStrut);
}

TEST(ClearanceIndex, AStrutThroughAFaceIsRefused)
{
    // A B1 strut along z through the centre of the bottom face, from below to the cube's centre.
    LocalChange c;
    const ZVec a = at(1, 0, 1, 0, -1, 0), b = at(1, 0, 1, 0, 1, 0);
    c.add_node(a);
    c.add_node(b);
    c.add_strut(a, b);
    EXPECT_EQ(check_on_cube(c), ClashKind::StrutFace);
}

TEST(ClearanceIndex, AFarAwayChangeIsAccepted)
{
    LocalChange c;
    const ZVec a = at(0, 6, 0, 0, 0, 0), b = at(2, 6, 0, 0, 0, 0); // (3, 0, 0) to (3 + φ, 0, 0)
    c.add_node(a);
    c.add_node(b);
    c.add_strut(a, b);
    EXPECT_EQ(check_on_cube(c), ClashKind::None);
}

Vec3 point(const ZVec& p)
{
    const auto c = p.to_double();
    return {c[0], c[1], c[2]};
}

// Every clash of the mesh by brute force (small meshes only).
int count_clashes(const ZomeMesh& mesh)
{
    std::vector<ZVec> balls;
    for (Vertex v : vertices(mesh))
        balls.push_back(mesh.position(v));
    std::vector<std::array<ZVec, 2>> struts;
    for (Edge e : edges(mesh))
        struts.push_back({mesh.position(mesh.vertex(e, 0)), mesh.position(mesh.vertex(e, 1))});
    std::vector<std::vector<ZVec>> polygons;
    for (Face f : faces(mesh))
    {
        polygons.emplace_back();
        for (Vertex v : face_vertices(mesh, f))
            polygons.back().push_back(mesh.position(v));
    }
    int clashes = 0;
    for (size_t i = 0; i < balls.size(); ++i)
        for (size_t j = i + 1; j < balls.size(); ++j)
            clashes += (point(balls[i]) - point(balls[j])).squaredNorm() < kMinBallBall * kMinBallBall;
    for (const ZVec& b : balls)
        for (const auto& s : struts)
            if (b != s[0] && b != s[1])
                clashes +=
                    point_segment_distance_squared(point(b), point(s[0]), point(s[1])) < kMinBallStrut * kMinBallStrut;
    for (size_t i = 0; i < struts.size(); ++i)
        for (size_t j = i + 1; j < struts.size(); ++j)
        {
            const auto& s = struts[i];
            const auto& t = struts[j];
            if (s[0] == t[0] || s[0] == t[1] || s[1] == t[0] || s[1] == t[1])
                continue;
            clashes += segment_segment_distance_squared(point(s[0]), point(s[1]), point(t[0]), point(t[1])) <
                       kMinStrutStrut * kMinStrutStrut;
        }
    for (const auto& s : struts)
        for (const auto& f : polygons)
        {
            if (std::find(f.begin(), f.end(), s[0]) != f.end() || std::find(f.begin(), f.end(), s[1]) != f.end())
                continue;
            const FaceShape shape = face_shape(f);
            for (int k = 0; k < shape.count; ++k)
            {
                const auto& t = shape.triangles[k];
                if (segment_intersects_triangle(point(s[0]), point(s[1]), t[0], t[1], t[2]))
                {
                    ++clashes;
                    break;
                }
            }
        }
    return clashes;
}

TEST(ClearanceIndex, RandomProposalsAreRefusedExactlyWhenTheyWouldClash)
{
    ZomeMesh mesh = from_model(fixtures::voxel_surface(fixtures::torus_cells(), fixtures::rhombohedral_basis()));
    ASSERT_EQ(count_clashes(mesh), 0);
    ClearanceIndex index(dilated(Box3{Vec3::Constant(-4.0), Vec3::Constant(8.0)}, 2.0));
    index.reset(mesh);
    Rng rng(7);
    Proposal p;
    int refused = 0, applied = 0;
    for (int step = 0; step < 20000 && applied < 400; ++step)
    {
        const auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
        if (!test::propose_at(kind, mesh, test::random_node(mesh, rng), rng, p))
            continue;
        const ClashKind clash = index.check(p.change);
        ZomeMesh after = mesh;
        apply_proposal(after, p);
        const int clashes = count_clashes(after);
        SCOPED_TRACE(::testing::Message() << "step " << step << " " << operator_name(kind) << " " << clash_name(clash));
        if (clash != ClashKind::None)
        {
            EXPECT_GT(clashes, 0);
            ++refused;
            continue;
        }
        ASSERT_EQ(clashes, 0);
        FixedList<Face, LocalChange::kMaxFaces> added;
        index.forget(p.change);
        apply_proposal(mesh, p, &added);
        index.learn(mesh, p.change, std::span<const Face>(added.begin(), added.size()));
        ++applied;
    }
    EXPECT_GT(refused, 10);
    EXPECT_GE(applied, 400);
}

} // namespace
} // namespace zomeify

namespace zomeify {
namespace {

// Z0 is made of B1 cubes: balls at least b1 apart, struts along the grid, faces on cube sides. It
// must pass the rule the annealer holds every commit to.
TEST(ClearanceIndex, InitialModelsOfTheSharedMeshesHaveNoClashes)
{
    ZOME_REQUIRE_SHARED();
    for (const char* name : {"bunny.obj", "fertility.obj", "rockerarm.obj", "elk.obj", "eight.obj", "3holes.obj",
                             "scorpion.obj", "sphere.obj", "torus.obj", "cube.obj"})
        for (int resolution : {12, 16})
        {
            const test::SharedScene scene = test::shared_scene(name, resolution);
            const ClearanceReport report = clearance_report(from_model(scene.z0));
            EXPECT_EQ(report.total(), 0u) << name << " at " << resolution << ": " << clearance_summary(report);
            EXPECT_GE(report.ball_ball, kMinBallBall) << name;
        }
}

} // namespace
} // namespace zomeify
