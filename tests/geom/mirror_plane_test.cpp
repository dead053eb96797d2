// The best mirror plane of a surface (issue 41, item 1): found on symmetric shapes made in code,
// wherever they are turned and moved; chiral and lopsided shapes are reported far from symmetric.
#include <cmath>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "core/base/errors.h"
#include "core/geom/mirror_plane.h"
#include "core/surface/prepare.h"
#include "tests/geom/geom_reference.h"
#include "tests/support/generated_shapes.h"
#include "tests/support/geom_fixtures.h"
#include "tests/support/paths.h"

namespace zomeify {
namespace {

// The mesh turned by `turn` and moved by `shift`.
TriangleMesh moved(TriangleMesh mesh, const Eigen::Matrix3d& turn, const Vec3& shift)
{
    for (Vec3& p : mesh.positions)
        p = turn * p + shift;
    return mesh;
}

const Eigen::Matrix3d kTurn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
const Vec3 kShift(3.0, -1.5, 0.25);

TEST(MirrorPlane, TheMugIsSymmetricAboutThePlaneThroughItsHandle)
{
    const test::GeneratedShape& mug = test::generated_shapes()[2];
    const SurfaceProjector surface(moved(mug.mesh, kTurn, kShift));
    const MirrorPlane m = find_mirror_plane(surface);
    // The mug's plane is z = 0 before the turn.
    const Vec3 expected = kTurn * Vec3::UnitZ();
    EXPECT_GT(std::abs(m.normal.dot(expected)), std::cos(0.5 * M_PI / 180.0)) << m.normal.transpose();
    EXPECT_NEAR(m.normal.dot(expected) * m.offset, expected.dot(kShift), 1e-3 * m.diagonal);
    // Marching tetrahedra do not split cells symmetrically: the two sides differ by a fraction of a cell.
    EXPECT_LT(m.rms, 2e-3 * m.diagonal);
    EXPECT_LT(m.max, 1e-2 * m.diagonal);
}

TEST(MirrorPlane, ATorusIsSymmetricAboutAPlaneOfItsOwn)
{
    const SurfaceProjector surface(moved(test::make_torus(1.0, 0.35, 64, 32), kTurn, kShift));
    const MirrorPlane m = find_mirror_plane(surface);
    EXPECT_LT(m.rms, 1e-3 * m.diagonal);
    // Any plane through the axis, or the equator: the reflection maps the torus onto itself.
    const Vec3 axis = kTurn * Vec3::UnitZ();
    const double along = std::abs(m.normal.dot(axis));
    EXPECT_TRUE(along > 0.9999 || along < 0.0175) << m.normal.transpose();
}

TEST(MirrorPlane, AKnotHasNoMirrorPlane)
{
    // A trefoil is chiral: no reflection maps it onto itself.
    const test::GeneratedShape& knot = test::generated_shapes()[0];
    const SurfaceProjector surface(knot.mesh);
    const MirrorPlane m = find_mirror_plane(surface);
    EXPECT_GT(m.rms, 2e-2 * m.diagonal);
}

TEST(MirrorPlane, AWrongPlaneMeasuresFar)
{
    const test::GeneratedShape& mug = test::generated_shapes()[2];
    const SurfaceProjector surface(mug.mesh);
    const MirrorPlane right = measure_mirror_plane(surface, Vec3::UnitZ(), 0.0);
    const MirrorPlane wrong = measure_mirror_plane(surface, Vec3::UnitX(), 0.0);
    EXPECT_LT(right.rms, 2e-3 * right.diagonal);
    EXPECT_GT(wrong.rms, 20 * right.rms);
    EXPECT_THROW(measure_mirror_plane(surface, Vec3::Zero(), 0.0), InvalidInputError);
}

TEST(MirrorPlane, ASurfaceWithoutAreaIsRefused)
{
    TriangleMesh flat;
    flat.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
    flat.triangles = {{0, 1, 2}};
    const SurfaceProjector surface(flat);
    EXPECT_THROW(find_mirror_plane(surface), InvalidInputError);
}

TEST(MirrorPlane, TheBunnyIsNotSymmetric)
{
    ZOME_REQUIRE_SHARED();
    const SurfaceProjector surface(load_surface(test::shared_mesh_path("bunny.obj")));
    const MirrorPlane m = find_mirror_plane(surface);
    EXPECT_GT(m.rms, 1e-2 * m.diagonal);
}

} // namespace
} // namespace zomeify
