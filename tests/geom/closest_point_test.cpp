#include "core/geom/closest_point.h"

#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/geom/geom_reference.h"
#include "tests/support/geom_fixtures.h"

namespace zomeify {
namespace {

// π(p) against the brute-force minimum, and the answer internally consistent.
void check_against_brute_force(const SurfaceProjector& projector, const Vec3& p, double diagonal)
{
    const TriangleMesh& mesh = projector.mesh();
    const ClosestPoint cp = projector.project(p);
    const double expected = test::brute_force_distance_squared(mesh, p);
    ASSERT_NEAR(cp.distance_squared, expected, 1e-12 * (diagonal * diagonal + expected)) << "p = " << p.transpose();
    ASSERT_LT(cp.triangle, mesh.triangles.size());
    const auto& t = mesh.triangles[cp.triangle];
    const Vec3 q = cp.barycentric[0] * mesh.positions[t[0]] + cp.barycentric[1] * mesh.positions[t[1]] +
                   cp.barycentric[2] * mesh.positions[t[2]];
    EXPECT_LT((q - cp.point).norm(), 1e-12 * diagonal);
    EXPECT_NEAR((p - cp.point).squaredNorm(), cp.distance_squared, 1e-12 * diagonal * diagonal);
    EXPECT_NEAR(cp.normal.norm(), 1.0, 1e-12);
}

TEST(GeomProjection, MatchesBruteForceOnProceduralSurfaces)
{
    std::mt19937 rng(11);
    for (const auto& [name, mesh] : test::procedural_surfaces())
    {
        SCOPED_TRACE(name);
        const SurfaceProjector projector(mesh);
        const double diagonal = test::bbox_diagonal(mesh);
        for (int i = 0; i < 500; ++i)
        {
            check_against_brute_force(projector, test::random_point_in_box(mesh, 0.3, rng), diagonal);
            check_against_brute_force(projector, test::random_point_near_surface(mesh, 0.05 * diagonal, rng), diagonal);
        }
        // Far away and exactly on vertices.
        check_against_brute_force(projector, Vec3(1e3, -2e3, 5e2), diagonal);
        for (size_t v = 0; v < mesh.positions.size(); v += 17)
        {
            const ClosestPoint cp = projector.project(mesh.positions[v]);
            EXPECT_EQ(cp.distance_squared, 0.0);
        }
    }
}

bool identical(const ClosestPoint& a, const ClosestPoint& b)
{
    return a.point == b.point && a.normal == b.normal && a.barycentric == b.barycentric &&
           a.distance_squared == b.distance_squared && a.triangle == b.triangle && a.feature == b.feature;
}

TEST(GeomProjection, HintGivesTheSameAnswerBitForBit)
{
    const TriangleMesh mesh = test::make_torus(1.0, 0.3, 40, 20);
    const SurfaceProjector projector(mesh);
    std::mt19937 rng(12);
    std::uniform_int_distribution<uint32_t> tri(0, static_cast<uint32_t>(mesh.triangles.size() - 1));
    int ties = 0;
    for (int i = 0; i < 4000; ++i)
    {
        // Half the points outside the torus near a vertex, where several triangles tie (the
        // closest point is the vertex itself), as strut midpoints and nodes often are.
        const Vec3 p = i % 2 ? test::random_point_in_box(mesh, 0.2, rng)
                             : Vec3(1.02 * mesh.positions[tri(rng) % mesh.positions.size()]);
        const ClosestPoint plain = projector.project(p);
        ties += plain.feature == TriangleFeature::face ? 0 : 1;
        ASSERT_TRUE(identical(plain, projector.project(p, tri(rng)))) << "point " << i;
        ASSERT_TRUE(identical(plain, projector.project(p, plain.triangle)));
    }
    EXPECT_GT(ties, 1000);
    EXPECT_EQ(projector.project(Vec3(3, 0, 0), 0xffffffffu).distance_squared,
              projector.project(Vec3(3, 0, 0)).distance_squared);
}

TEST(GeomProjection, ExtremeScalesAndFarQueriesMatchBruteForce)
{
    // Tiny and huge meshes and queries far outside float range take the exact scan of all
    // triangles; a mesh away from the coordinate origin is searched relative to its box.
    std::mt19937 rng(17);
    const TriangleMesh unit = test::make_torus(1.0, 0.3, 24, 12);
    for (const double scale : {1e-20, 1.0, 1e20})
    {
        for (const double shift : {0.0, 100.0})
        {
            TriangleMesh mesh = unit;
            for (Vec3& v : mesh.positions)
            {
                v = scale * v + Vec3(shift * scale, -shift * scale, 0.5 * shift * scale);
            }
            SCOPED_TRACE(testing::Message() << "scale " << scale << ", shift " << shift);
            const SurfaceProjector projector(mesh);
            const double diagonal = test::bbox_diagonal(mesh);
            for (int i = 0; i < 100; ++i)
            {
                check_against_brute_force(projector, test::random_point_near_surface(mesh, 0.05 * diagonal, rng),
                                          diagonal);
            }
            const Vec3 centre = mesh.positions[0];
            check_against_brute_force(projector, centre + Vec3(1e17, -3e16, 2e16) * diagonal, diagonal);
        }
    }
}

TEST(GeomProjection, NormalsAreUnitAndOutwardOnAnalyticShapes)
{
    std::mt19937 rng(13);
    const SurfaceProjector sphere(test::make_uv_sphere(2.0, 32, 64));
    for (int i = 0; i < 3000; ++i)
    {
        const Vec3 p = test::random_point_in_box(sphere.mesh(), 0.5, rng);
        const ClosestPoint cp = sphere.project(p);
        EXPECT_NEAR(cp.normal.norm(), 1.0, 1e-12);
        EXPECT_GT(cp.normal.dot(cp.point.normalized()), 0.995);
    }
    const double major = 1.0;
    const SurfaceProjector torus(test::make_torus(major, 0.3, 96, 48));
    for (int i = 0; i < 3000; ++i)
    {
        const Vec3 p = test::random_point_in_box(torus.mesh(), 0.3, rng);
        const ClosestPoint cp = torus.project(p);
        const Vec3 ring = major * Vec3(cp.point.x(), 0, cp.point.z()).normalized();
        const Vec3 exact = (cp.point - ring).normalized();
        EXPECT_NEAR(cp.normal.norm(), 1.0, 1e-12);
        EXPECT_GT(cp.normal.dot(exact), 0.99);
    }
}

TEST(GeomProjection, NormalsPointOutwardOnTheCube)
{
    // Sharp edges and corners: the interpolated normal still leans outward of the closest face.
    const SurfaceProjector cube(test::make_cube(1.0, 3));
    std::mt19937 rng(14);
    for (int i = 0; i < 3000; ++i)
    {
        const ClosestPoint cp = cube.project(test::random_point_in_box(cube.mesh(), 0.5, rng));
        EXPECT_GT(cp.normal.dot(cube.face_normals()[cp.triangle]), 0.5);
    }
    const ClosestPoint corner = cube.project(Vec3(2, 2, 2));
    EXPECT_NEAR(corner.normal.dot(Vec3(1, 1, 1).normalized()), 1.0, 1e-12);
}

TEST(GeomProjection, RejectsInvalidMeshes)
{
    EXPECT_ANY_THROW(SurfaceProjector(TriangleMesh{}));
    TriangleMesh bad_index = test::make_icosphere(1.0, 0);
    bad_index.triangles[3][1] = 99;
    EXPECT_ANY_THROW(SurfaceProjector{bad_index});
    TriangleMesh nan = test::make_icosphere(1.0, 0);
    nan.positions[2].y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_ANY_THROW(SurfaceProjector{nan});
}

TEST(GeomProjection, DegenerateTrianglesInTheMesh)
{
    // A zero-area triangle glued into the soup must not break queries or normals.
    TriangleMesh mesh = test::make_icosphere(1.0, 1);
    const auto n = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.push_back(Vec3(0.2, 0.2, 0.2));
    mesh.positions.push_back(Vec3(0.4, 0.4, 0.4));
    mesh.positions.push_back(Vec3(0.6, 0.6, 0.6));
    mesh.triangles.push_back({n, n + 1, n + 2});
    const SurfaceProjector projector(mesh);
    std::mt19937 rng(15);
    const double diagonal = test::bbox_diagonal(mesh);
    for (int i = 0; i < 1000; ++i)
    {
        check_against_brute_force(projector, test::random_point_in_box(mesh, 0.2, rng), diagonal);
    }
}

TEST(GeomProjection, ConcurrentQueriesGiveTheSameAnswers)
{
    const TriangleMesh mesh = test::make_torus(1.0, 0.25, 64, 32);
    const SurfaceProjector projector(mesh);
    std::mt19937 rng(16);
    std::vector<Vec3> points;
    for (int i = 0; i < 4000; ++i)
    {
        points.push_back(test::random_point_near_surface(mesh, 0.1, rng));
    }
    std::vector<ClosestPoint> expected;
    for (const Vec3& p : points)
    {
        expected.push_back(projector.project(p));
    }
    std::vector<int> mismatches(4, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
    {
        threads.emplace_back([&, t] {
            for (size_t i = 0; i < points.size(); ++i)
            {
                const size_t k = (i * 7 + static_cast<size_t>(t) * 1000) % points.size();
                const ClosestPoint cp = projector.project(points[k]);
                mismatches[t] += cp.distance_squared == expected[k].distance_squared &&
                                         cp.triangle == expected[k].triangle && cp.normal == expected[k].normal
                                     ? 0
                                     : 1;
            }
        });
    }
    for (std::thread& th : threads)
    {
        th.join();
    }
    for (int t = 0; t < 4; ++t)
    {
        EXPECT_EQ(mismatches[t], 0);
    }
}

} // namespace
} // namespace zomeify
