#include "core/geom/inside.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "tests/geom/geom_reference.h"
#include "tests/support/geom_fixtures.h"

namespace zomeify {
namespace {

TEST(GeomInside, FixturesAreClosedAndOutward)
{
    for (const auto& [name, mesh] : test::procedural_surfaces())
    {
        EXPECT_GT(test::signed_volume(mesh), 0.0) << name;
    }
}

TEST(GeomInside, AgreesWithRayParityOnProceduralSurfaces)
{
    std::mt19937 rng(21);
    for (const auto& [name, mesh] : test::procedural_surfaces())
    {
        SCOPED_TRACE(name);
        const SurfaceProjector projector(mesh);
        const InsideTest inside(projector);
        const double diagonal = test::bbox_diagonal(mesh);
        int checked = 0;
        int inside_count = 0;
        for (int i = 0; i < 600; ++i)
        {
            const Vec3 p = i % 2 == 0 ? test::random_point_in_box(mesh, 0.0, rng)
                                      : test::random_point_near_surface(mesh, 0.02 * diagonal, rng);
            const ClosestPoint cp = projector.project(p);
            if (cp.distance_squared <= 1e-12 * diagonal * diagonal)
            {
                continue;
            }
            ++checked;
            const bool expected = test::ray_parity_inside(mesh, p);
            inside_count += expected ? 1 : 0;
            ASSERT_EQ(inside.is_inside(p), expected) << "p = " << p.transpose();
            EXPECT_EQ(inside.is_inside(p, cp), expected);
            const double sd = inside.signed_distance(p);
            EXPECT_NEAR(std::abs(sd), std::sqrt(cp.distance_squared), 1e-15 * diagonal);
            EXPECT_EQ(sd < 0.0, expected);
        }
        EXPECT_GT(checked, 550);
        EXPECT_GT(inside_count, 50);
    }
}

TEST(GeomInside, CornersAndEdgesOfTheCube)
{
    // Off the cube's corners and edges the closest feature is a vertex or an edge, where a single
    // face normal would give the wrong side; the pseudo-normals must not.
    const SurfaceProjector projector(test::make_cube(1.0, 1));
    const InsideTest inside(projector);
    for (int sx : {-1, 1})
    {
        for (int sy : {-1, 1})
        {
            for (int sz : {-1, 1})
            {
                const Vec3 s(sx, sy, sz);
                EXPECT_FALSE(inside.is_inside(1.001 * s));
                EXPECT_TRUE(inside.is_inside(0.999 * s));
                EXPECT_FALSE(inside.is_inside(Vec3(1.01 * sx, 1.02 * sy, 0.3 * sz)));
                EXPECT_TRUE(inside.is_inside(Vec3(0.99 * sx, 0.98 * sy, 0.3 * sz)));
                EXPECT_FALSE(inside.is_inside(Vec3(1.5 * sx, 1.0000001 * sy, 0.0)));
            }
        }
    }
    EXPECT_NEAR(inside.signed_distance(Vec3(0, 0, 0)), -1.0, 1e-15);
    EXPECT_NEAR(inside.signed_distance(Vec3(2, 2, 1)), std::sqrt(2.0), 1e-15);
    EXPECT_FALSE(inside.is_inside(Vec3(1, 0.5, 0.5))); // on S counts as outside
}

TEST(GeomInside, ThinTorusRing)
{
    // Points inside a thin tube are close to faces on both sides of it.
    const TriangleMesh mesh = test::make_torus(1.0, 0.02, 128, 12);
    const SurfaceProjector projector(mesh);
    const InsideTest inside(projector);
    std::mt19937 rng(22);
    for (int i = 0; i < 300; ++i)
    {
        const Vec3 p = test::random_point_near_surface(mesh, 0.03, rng);
        if (projector.project(p).distance_squared < 1e-12)
        {
            continue;
        }
        ASSERT_EQ(inside.is_inside(p), test::ray_parity_inside(mesh, p)) << "p = " << p.transpose();
    }
}

} // namespace
} // namespace zomeify
