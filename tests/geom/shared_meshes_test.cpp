// π(p), normals and the inside test on the ten shared meshes (ZOME_SHARED_DIR/data/meshes),
// loaded through core/surface like the real pipeline does.
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "core/geom/inside.h"
#include "core/surface/prepare.h"
#include "tests/geom/geom_reference.h"

namespace zomeify {
namespace {

class GeomSharedMeshes : public ::testing::TestWithParam<std::string>
{
};

TEST_P(GeomSharedMeshes, ProjectionMatchesBruteForceWithOutwardUnitNormals)
{
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

TEST_P(GeomSharedMeshes, InsideAgreesWithRayParity)
{
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
