// π(p), normals and the inside test on the ten shared meshes (ZOME_SHARED_DIR/data/meshes),
// loaded through core/surface like the real pipeline does.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/geom/inside.h"
#include "core/surface/prepare.h"
#include "tests/geom/geom_reference.h"
#include "tests/support/paths.h"

namespace zomeify {
namespace {

class GeomSharedMeshes : public ::testing::TestWithParam<std::string>
{
};

TEST_P(GeomSharedMeshes, ProjectionMatchesBruteForceWithOutwardUnitNormals)
{
    ZOME_REQUIRE_SHARED();
    const TriangleMesh mesh = load_surface(test::shared_mesh_path(GetParam()));
    const SurfaceProjector projector(mesh);
    const double diagonal = test::bbox_diagonal(mesh);
    std::mt19937 rng(31);
    for (int i = 0; i < 160; ++i)
    {
        // Alternate: anywhere around the model, and within 2 voxel sizes (diagonal / 24) of S.
        const Vec3 p = i % 2 == 0 ? test::random_point_in_box(mesh, 0.1, rng)
                                  : test::random_point_near_surface(mesh, diagonal / 12.0, rng);
        const ClosestPoint cp = projector.project(p);
        const double expected = test::brute_force_distance_squared(mesh, p);
        ASSERT_NEAR(cp.distance_squared, expected, 1e-12 * (diagonal * diagonal + expected)) << "p = " << p.transpose();
        EXPECT_NEAR(cp.normal.norm(), 1.0, 1e-12);
        EXPECT_GT(cp.normal.dot(projector.face_normals()[cp.triangle]), 0.0) << "p = " << p.transpose();
    }
}

TEST_P(GeomSharedMeshes, ProjectionMatchesBruteForceOnAndFarFromTheSurface)
{
    ZOME_REQUIRE_SHARED();
    // The float search with exact refinement (TriangleBlock estimates) against brute force where
    // its error bounds are tightest (points on S: distance 0, ties between the triangles around a
    // vertex or along an edge) and loosest (far away: the float magnitude grows with the
    // distance). A hint must give the same distance.
    const TriangleMesh mesh = load_surface(test::shared_mesh_path(GetParam()));
    const SurfaceProjector projector(mesh);
    const double diagonal = test::bbox_diagonal(mesh);
    std::mt19937 rng(33);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::uniform_int_distribution<size_t> pick(0, mesh.triangles.size() - 1);
    std::normal_distribution<double> g(0.0, 1.0);
    std::vector<Vec3> points;
    for (int i = 0; i < 40; ++i)
    {
        const auto& t = mesh.triangles[pick(rng)];
        const double w = u(rng);
        const double v = (1.0 - w) * u(rng);
        const Vec3 on = (1.0 - w - v) * mesh.positions[t[0]] + v * mesh.positions[t[1]] + w * mesh.positions[t[2]];
        points.push_back(on);
        points.push_back(mesh.positions[t[i % 3]]);
        points.push_back(0.5 * (mesh.positions[t[i % 3]] + mesh.positions[t[(i + 1) % 3]]));
        const Vec3 dir = Vec3(g(rng), g(rng), g(rng)).normalized();
        points.push_back(on + diagonal * std::pow(10.0, 3.0 * u(rng)) * dir);
    }
    for (const Vec3& p : points)
    {
        const ClosestPoint cp = projector.project(p);
        const double expected = test::brute_force_distance_squared(mesh, p);
        ASSERT_NEAR(cp.distance_squared, expected, 1e-12 * (diagonal * diagonal + expected)) << "p = " << p.transpose();
        EXPECT_EQ(projector.project(p, static_cast<uint32_t>(pick(rng))).distance_squared, cp.distance_squared)
            << "p = " << p.transpose();
    }
}

TEST_P(GeomSharedMeshes, InsideAgreesWithRayParity)
{
    ZOME_REQUIRE_SHARED();
    const TriangleMesh mesh = load_surface(test::shared_mesh_path(GetParam()));
    const SurfaceProjector projector(mesh);
    const InsideTest inside(projector);
    const double diagonal = test::bbox_diagonal(mesh);
    const double skip = 1e-6 * diagonal;
    std::mt19937 rng(32);
    int checked = 0;
    int inside_count = 0;
    for (int i = 0; i < 300; ++i)
    {
        const Vec3 p = test::random_point_in_box(mesh, 0.0, rng);
        const ClosestPoint cp = projector.project(p);
        if (cp.distance_squared <= skip * skip)
        {
            continue;
        }
        ++checked;
        const bool expected = test::ray_parity_inside(mesh, p);
        inside_count += expected ? 1 : 0;
        ASSERT_EQ(inside.is_inside(p, cp), expected) << "p = " << p.transpose();
    }
    EXPECT_GT(checked, 290);
    EXPECT_GT(inside_count, 0);
}

INSTANTIATE_TEST_SUITE_P(GeomMeshes, GeomSharedMeshes, ::testing::ValuesIn(test::shared_mesh_names()),
                         [](const ::testing::TestParamInfo<std::string>& param_info) {
                             std::string name = param_info.param.substr(0, param_info.param.find('.'));
                             return name == "3holes" ? std::string("holes3") : name;
                         });

} // namespace
} // namespace zomeify
