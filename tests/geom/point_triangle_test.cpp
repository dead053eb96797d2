#include "core/geom/point_triangle.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "tests/geom/geom_reference.h"

namespace zomeify {
namespace {

Vec3 random_vec(std::mt19937& rng, double scale)
{
    std::uniform_real_distribution<double> u(-scale, scale);
    return Vec3(u(rng), u(rng), u(rng));
}

// The answer must be a point of the triangle at the distance it claims.
void expect_consistent(const TrianglePoint& r, const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
    ASSERT_TRUE(r.point.allFinite());
    EXPECT_GE(r.barycentric.minCoeff(), 0.0);
    EXPECT_NEAR(r.barycentric.sum(), 1.0, 1e-12);
    const Vec3 q = r.barycentric[0] * a + r.barycentric[1] * b + r.barycentric[2] * c;
    const double scale = std::max({a.norm(), b.norm(), c.norm(), 1.0});
    EXPECT_LT((q - r.point).norm(), 1e-12 * scale);
    EXPECT_NEAR(r.distance_squared, (p - r.point).squaredNorm(), 1e-12 * scale * scale);
}

TEST(GeomPointTriangle, MatchesReferenceOnRandomTriangles)
{
    std::mt19937 rng(1);
    for (int i = 0; i < 20000; ++i)
    {
        const Vec3 a = random_vec(rng, 1.0), b = random_vec(rng, 1.0), c = random_vec(rng, 1.0);
        const Vec3 p = random_vec(rng, 2.0);
        const TrianglePoint r = closest_point_on_triangle(p, a, b, c);
        expect_consistent(r, p, a, b, c);
        EXPECT_NEAR(r.distance_squared, test::reference_triangle_distance_squared(p, a, b, c), 1e-12);
    }
}

TEST(GeomPointTriangle, RobustOnSliversAndDegenerateTriangles)
{
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 20000; ++i)
    {
        const Vec3 a = random_vec(rng, 1.0);
        const Vec3 b = random_vec(rng, 1.0);
        Vec3 c;
        switch (i % 5)
        {
        case 0: // collinear, c between a and b
            c = a + u(rng) * (b - a);
            break;
        case 1: // collinear, c beyond b
            c = a + (1.0 + u(rng)) * (b - a);
            break;
        case 2: // two corners coincide
            c = b;
            break;
        case 3: // all three coincide
            c = a;
            break;
        default: // sliver: tiny height over ab
            c = a + u(rng) * (b - a) + 1e-9 * random_vec(rng, 1.0);
            break;
        }
        const Vec3 p = random_vec(rng, 2.0);
        const Vec3& bb = (i % 5 == 3) ? a : b;
        const TrianglePoint r = closest_point_on_triangle(p, a, bb, c);
        expect_consistent(r, p, a, bb, c);
        EXPECT_NEAR(r.distance_squared, test::reference_triangle_distance_squared(p, a, bb, c), 1e-8);
    }
}

TEST(GeomPointTriangle, AnyTwoCoincidentCornersMeasureTheRemainingSegment)
{
    // With a == b the region walk alone would take corner a's region for the whole segment ac.
    std::mt19937 rng(3);
    for (int i = 0; i < 6000; ++i)
    {
        const Vec3 x = random_vec(rng, 1.0);
        const Vec3 y = random_vec(rng, 1.0);
        const Vec3 corners[3][3] = {{x, x, y}, {x, y, x}, {y, x, x}};
        const Vec3(&t)[3] = corners[i % 3];
        const Vec3 p = random_vec(rng, 2.0);
        const double expected = test::reference_triangle_distance_squared(p, t[0], t[1], t[2]);
        const TrianglePoint r = closest_point_on_triangle(p, t[0], t[1], t[2]);
        expect_consistent(r, p, t[0], t[1], t[2]);
        EXPECT_NEAR(r.distance_squared, expected, 1e-12);
        EXPECT_NEAR(point_triangle_distance_squared(p, t[0], t[1], t[2]), expected, 1e-12);
    }
}

TEST(GeomPointTriangle, ReportsTheFeature)
{
    const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    EXPECT_EQ(closest_point_on_triangle(Vec3(0.2, 0.2, 1), a, b, c).feature, TriangleFeature::face);
    EXPECT_EQ(closest_point_on_triangle(Vec3(-1, -1, 0), a, b, c).feature, TriangleFeature::vertex0);
    EXPECT_EQ(closest_point_on_triangle(Vec3(2, -0.5, 0), a, b, c).feature, TriangleFeature::vertex1);
    EXPECT_EQ(closest_point_on_triangle(Vec3(-0.5, 2, 0), a, b, c).feature, TriangleFeature::vertex2);
    EXPECT_EQ(closest_point_on_triangle(Vec3(0.5, -1, 0), a, b, c).feature, TriangleFeature::edge01);
    EXPECT_EQ(closest_point_on_triangle(Vec3(1, 1, 0.3), a, b, c).feature, TriangleFeature::edge12);
    EXPECT_EQ(closest_point_on_triangle(Vec3(-1, 0.5, 0), a, b, c).feature, TriangleFeature::edge20);
    const TrianglePoint r = closest_point_on_triangle(Vec3(0.25, 0.5, 3), a, b, c);
    EXPECT_NEAR(r.distance_squared, 9.0, 1e-15);
    EXPECT_NEAR(r.barycentric[1], 0.25, 1e-15);
    EXPECT_NEAR(r.barycentric[2], 0.5, 1e-15);
}

} // namespace
} // namespace zomeify
