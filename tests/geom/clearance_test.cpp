// The clearance predicates: exact answers on configurations whose arithmetic is exact in double,
// the degenerate cases (parallel, collinear, zero-length, coplanar, touching), independence of
// argument order, and agreement with slow references on random input.
#include "core/geom/clearance.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/zome/qphi.h"
#include "core/zome/zvec.h"

namespace zomeify {
namespace {

Vec3 random_vec(std::mt19937& rng, double scale)
{
    std::uniform_real_distribution<double> u(-scale, scale);
    return Vec3(u(rng), u(rng), u(rng));
}

Vec3 lattice(const ZVec& p)
{
    const auto d = p.to_double();
    return {d[0], d[1], d[2]};
}

ZVec times(const ZVec& v, int k)
{
    ZVec out;
    for (int i = 0; i < 6; ++i)
        out.c[i] = v.c[i] * k;
    return out;
}

// Slow reference: the distance of a point of the first segment to the second is convex in its
// parameter, so a ternary search over it with an exact inner step finds the minimum.
double reference_segment_distance_squared(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1)
{
    const auto at = [&](double s) { return point_segment_distance_squared(p0 + s * (p1 - p0), q0, q1); };
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200; ++i)
    {
        const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
        if (at(m1) < at(m2))
            hi = m2;
        else
            lo = m1;
    }
    return std::min({at(0.5 * (lo + hi)), at(0.0), at(1.0)});
}

TEST(GeomClearance, PointSegmentExactAnswers)
{
    const Vec3 a(-1, 0, 0), b(1, 0, 0);
    EXPECT_EQ(point_segment_distance_squared(Vec3(0, 1, 0), a, b), 1.0);   // above the middle
    EXPECT_EQ(point_segment_distance_squared(Vec3(0.5, 0, 0), a, b), 0.0); // on the segment
    EXPECT_EQ(point_segment_distance_squared(Vec3(3, 0, 0), a, b), 4.0);   // beyond an end, collinear
    EXPECT_EQ(point_segment_distance_squared(Vec3(-2, 2, 0), a, b), 5.0);  // beyond the other end
    EXPECT_EQ(point_segment_distance_squared(Vec3(1, 0, 0), a, b), 0.0);   // at an end
    const Vec3 c(1, 2, 3);
    EXPECT_EQ(point_segment_distance_squared(Vec3(1, 2, 5), c, c), 4.0); // zero-length segment
}

TEST(GeomClearance, SegmentSegmentExactAnswers)
{
    const Vec3 x0(-1, 0, 0), x1(1, 0, 0);
    // Skew perpendicular segments crossing one above the other.
    SegmentClosest c = segment_segment_closest(x0, x1, Vec3(0, -1, 1), Vec3(0, 1, 1));
    EXPECT_EQ(c.distance_squared, 1.0);
    EXPECT_EQ(c.s, 0.5);
    EXPECT_EQ(c.t, 0.5);
    // Crossing: distance 0.
    EXPECT_EQ(segment_segment_distance_squared(x0, x1, Vec3(0, -1, 0), Vec3(0, 1, 0)), 0.0);
    // A T: an end on the middle of the other.
    EXPECT_EQ(segment_segment_distance_squared(x0, x1, Vec3(0, 0, 0), Vec3(0, 0, 2)), 0.0);
    // Skew, closest points at ends of both.
    EXPECT_EQ(segment_segment_distance_squared(x0, x1, Vec3(2, 1, 0), Vec3(2, 3, 0)), 2.0);
    // Parallel, overlapping in x, 1 apart; and parallel with no overlap.
    EXPECT_EQ(segment_segment_distance_squared(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(3, 1, 0)), 1.0);
    EXPECT_EQ(segment_segment_distance_squared(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 1, 0), Vec3(4, 1, 0)), 5.0);
    // Anti-parallel with the same overlap.
    EXPECT_EQ(segment_segment_distance_squared(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(3, 1, 0), Vec3(1, 1, 0)), 1.0);
    // Collinear: apart, touching at an end, overlapping, one inside the other.
    EXPECT_EQ(segment_segment_distance_squared(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(4, 0, 0)), 4.0);
    EXPECT_EQ(segment_segment_distance_squared(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(4, 0, 0)), 0.0);
    EXPECT_EQ(segment_segment_distance_squared(Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 0), Vec3(4, 0, 0)), 0.0);
    EXPECT_EQ(segment_segment_distance_squared(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)), 0.0);
    // Zero-length: a point and a segment, two points, the same point twice.
    EXPECT_EQ(segment_segment_distance_squared(Vec3(0, 3, 0), Vec3(0, 3, 0), x0, x1), 9.0);
    EXPECT_EQ(segment_segment_distance_squared(x0, x1, Vec3(0, 3, 0), Vec3(0, 3, 0)), 9.0);
    EXPECT_EQ(segment_segment_distance_squared(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 3, 1), Vec3(1, 3, 1)), 4.0);
    EXPECT_EQ(segment_segment_distance_squared(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)), 0.0);
}

TEST(GeomClearance, ClosestPointsAreOnTheSegmentsAtTheDistance)
{
    std::mt19937 rng(3);
    for (int i = 0; i < 2000; ++i)
    {
        const Vec3 p0 = random_vec(rng, 1), p1 = random_vec(rng, 1), q0 = random_vec(rng, 1), q1 = random_vec(rng, 1);
        const SegmentClosest c = segment_segment_closest(p0, p1, q0, q1);
        ASSERT_GE(c.s, 0.0);
        ASSERT_LE(c.s, 1.0);
        ASSERT_GE(c.t, 0.0);
        ASSERT_LE(c.t, 1.0);
        const Vec3 a = p0 + c.s * (p1 - p0), b = q0 + c.t * (q1 - q0);
        EXPECT_NEAR((a - b).squaredNorm(), c.distance_squared, 1e-12);
    }
}

TEST(GeomClearance, SegmentSegmentMatchesReference)
{
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 3000; ++i)
    {
        const Vec3 p0 = random_vec(rng, 1), p1 = random_vec(rng, 1);
        Vec3 q0 = random_vec(rng, 1), q1 = random_vec(rng, 1);
        switch (i % 4)
        {
        case 1: // parallel
            q1 = q0 + (p1 - p0) * (2.0 * u(rng) - 1.0);
            break;
        case 2: // nearly parallel
            q1 = q0 + (p1 - p0) + 1e-7 * random_vec(rng, 1);
            break;
        case 3: // collinear
            q0 = p0 + (3.0 * u(rng) - 1.0) * (p1 - p0);
            q1 = p0 + (3.0 * u(rng) - 1.0) * (p1 - p0);
            break;
        default:
            break;
        }
        const double d2 = segment_segment_distance_squared(p0, p1, q0, q1);
        const double ref = reference_segment_distance_squared(p0, p1, q0, q1);
        ASSERT_NEAR(std::sqrt(d2), std::sqrt(ref), 1e-7) << "case " << i;
        // Never below the truth by more than rounding: every candidate is a real pair of points.
        EXPECT_GE(d2, ref - 1e-12);
    }
}

TEST(GeomClearance, ArgumentOrderGivesBitIdenticalResults)
{
    std::mt19937 rng(5);
    for (int i = 0; i < 2000; ++i)
    {
        const Vec3 p0 = random_vec(rng, 10), p1 = random_vec(rng, 10), q0 = random_vec(rng, 10),
                   q1 = random_vec(rng, 10);
        const double d = segment_segment_distance_squared(p0, p1, q0, q1);
        EXPECT_EQ(d, segment_segment_distance_squared(p1, p0, q0, q1));
        EXPECT_EQ(d, segment_segment_distance_squared(p0, p1, q1, q0));
        EXPECT_EQ(d, segment_segment_distance_squared(q0, q1, p0, p1));
        EXPECT_EQ(d, segment_segment_distance_squared(q1, q0, p1, p0));
        const SegmentClosest c = segment_segment_closest(p0, p1, q0, q1);
        const SegmentClosest swapped = segment_segment_closest(q1, q0, p0, p1);
        EXPECT_NEAR(c.s, swapped.t, 1e-15);
        EXPECT_NEAR(c.t, 1.0 - swapped.s, 1e-15);
        EXPECT_EQ(point_segment_distance_squared(q0, p0, p1), point_segment_distance_squared(q0, p1, p0));
        const Vec3 a = random_vec(rng, 10), b = random_vec(rng, 10), cc = random_vec(rng, 10);
        const bool hit = segment_intersects_triangle(p0, p1, a, b, cc);
        EXPECT_EQ(hit, segment_intersects_triangle(p1, p0, cc, a, b));
        EXPECT_EQ(hit, segment_intersects_triangle(p0, p1, b, a, cc));
    }
}

TEST(GeomClearance, SegmentTriangleExactCases)
{
    const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    const auto hits = [&](Vec3 p, Vec3 q) { return segment_intersects_triangle(p, q, a, b, c); };
    EXPECT_TRUE(hits({0.5, 0.5, -1}, {0.5, 0.5, 1}));        // through the interior
    EXPECT_FALSE(hits({3, 3, -1}, {3, 3, 1}));               // beside it
    EXPECT_FALSE(hits({0.5, 0.5, 0.5}, {0.5, 0.5, 1}));      // above it, pointing at it
    EXPECT_TRUE(hits({0.5, 0.5, 0}, {0.5, 0.5, 1}));         // an end on the face
    EXPECT_FALSE(hits({0.5, 0.5, 1e-6}, {0.5, 0.5, 1}));     // an end just above it
    EXPECT_TRUE(hits({1, 0, -1}, {1, 0, 1}));                // through an edge
    EXPECT_TRUE(hits({1, 1, -1}, {1, 1, 1}));                // through the long edge's middle
    EXPECT_FALSE(hits({1 + 1e-9, 1, -1}, {1 + 1e-9, 1, 1})); // just outside it
    EXPECT_TRUE(hits({0, 0, -1}, {0, 0, 1}));                // through a corner
    EXPECT_TRUE(hits({2, 0, 0}, {3, 0, 5}));                 // an end on a corner
    EXPECT_TRUE(hits({-1, 1, 1}, {1, -1, -1}));              // slanted, through a corner
    EXPECT_FALSE(hits({-1, -1, 1}, {3, 3, 1}));              // parallel to the plane, above
    // Coplanar: across, wholly inside, along an edge, through a corner only, apart, collinear beyond.
    EXPECT_TRUE(hits({-1, 0.5, 0}, {3, 0.5, 0}));
    EXPECT_TRUE(hits({0.2, 0.2, 0}, {0.5, 0.5, 0}));
    EXPECT_TRUE(hits({-1, 0, 0}, {3, 0, 0}));
    EXPECT_TRUE(hits({3, -1, 0}, {1, 1, 0})); // ends on the long edge
    EXPECT_TRUE(hits({2, 0, 0}, {3, -1, 0})); // touches a corner from outside
    EXPECT_FALSE(hits({-1, 3, 0}, {3, 3, 0}));
    EXPECT_FALSE(hits({3, 0, 0}, {4, 0, 0}));
    // Zero-length segments: a point on and off the triangle.
    EXPECT_TRUE(hits({0.5, 0.5, 0}, {0.5, 0.5, 0}));
    EXPECT_FALSE(hits({0.5, 0.5, 0.1}, {0.5, 0.5, 0.1}));
    // A degenerate triangle (collinear corners) is its edges.
    const Vec3 d0(0, 0, 0), d1(1, 0, 0), d2(2, 0, 0);
    EXPECT_TRUE(segment_intersects_triangle({1.5, -1, 0}, {1.5, 1, 0}, d0, d1, d2));
    EXPECT_FALSE(segment_intersects_triangle({1.5, -1, 1e-3}, {1.5, 1, 1e-3}, d0, d1, d2));
    EXPECT_FALSE(segment_intersects_triangle({1, 0, 0}, {1, 0, 0}, d0, d0, d0)); // a point triangle off a point
    EXPECT_TRUE(segment_intersects_triangle({-1, 0, 0}, {1, 0, 0}, d0, d0, d0)); // a point triangle on the segment
}

// A quad's two canonical triangles share a diagonal: a strut through a point of it must hit one
// of them, whatever rounding does (the positions here are irrational, as on the Zome lattice).
TEST(GeomClearance, NoGapAlongASharedDiagonal)
{
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const Vec3 c0 = rot * Vec3(0.1, 0.2, 0.3), c1 = rot * Vec3(kPhi + 0.1, 0.2, 0.3);
    const Vec3 c2 = rot * Vec3(kPhi + 0.1, kPhi + 0.2, 0.3), c3 = rot * Vec3(0.1, kPhi + 0.2, 0.3);
    const Vec3 up = rot * Vec3(0.05, -0.03, 1.0);
    for (int i = 1; i < 1000; ++i)
    {
        const Vec3 on = c0 + (i / 1000.0) * (c2 - c0);
        const bool hit = segment_intersects_triangle(on - up, on + up, c0, c1, c2) ||
                         segment_intersects_triangle(on - up, on + up, c0, c2, c3);
        ASSERT_TRUE(hit) << i;
    }
}

// Exactly coplanar lattice configurations in a plane with irrational coordinates: the plane test
// cannot decide them exactly in double; the touching tolerance of clearance.h does.
TEST(GeomClearance, CoplanarLatticeSegments)
{
    const ZVec A{{1, 0, 0, 1, 0, 0}}; // (φ/2, 1/2, 0)
    const ZVec B{{0, 1, 1, 0, 0, 1}}; // (1/2, φ/2, 1/2)
    const ZVec C{{0, 0, 0, 1, 1, 1}}; // (0, 1/2, φ²/2)
    // The lattice point A + i(B − A) + j(C − A): exactly in the plane of A, B, C.
    const auto on = [&](int i, int j) { return lattice(A + times(B - A, i) + times(C - A, j)); };
    // The triangle with corners (0, 0), (3, 0), (0, 3): inside means i, j ≥ 0 and i + j ≤ 3.
    const auto hits = [&](Vec3 p, Vec3 q) { return segment_intersects_triangle(p, q, on(0, 0), on(3, 0), on(0, 3)); };
    EXPECT_TRUE(hits(on(-1, 1), on(3, 1)));   // across, through the centroid (1, 1)
    EXPECT_FALSE(hits(on(-1, 4), on(3, 4)));  // the same line past the corner (0, 3)
    EXPECT_TRUE(hits(on(-1, 1), on(1, 1)));   // ends at the centroid
    EXPECT_TRUE(hits(on(-1, 1), on(0, 1)));   // ends on the edge i = 0
    EXPECT_FALSE(hits(on(-2, 1), on(-1, 1))); // stops short of it
    EXPECT_TRUE(hits(on(-1, 0), on(0, 0)));   // collinear with an edge, ends at its corner
    EXPECT_FALSE(hits(on(-2, 0), on(-1, 0))); // collinear with an edge, apart
    EXPECT_TRUE(hits(on(4, -1), on(-1, 4)));  // along the line of the edge i + j = 3, past both corners
    EXPECT_FALSE(hits(on(5, -1), on(-1, 5))); // parallel to it, outside
}

TEST(GeomClearance, SegmentTriangleMatchesPlaneCrossingOnRandomInput)
{
    std::mt19937 rng(6);
    int hits = 0, tested = 0;
    for (int i = 0; i < 20000; ++i)
    {
        const Vec3 a = random_vec(rng, 1), b = random_vec(rng, 1), c = random_vec(rng, 1);
        const Vec3 p = random_vec(rng, 1.5), q = random_vec(rng, 1.5);
        // Reference: barycentric coordinates of the plane crossing, away from every boundary.
        const Vec3 n = (b - a).cross(c - a);
        const double dp = n.dot(p - a), dq = n.dot(q - a);
        const double margin = 1e-6 * n.norm();
        if (std::abs(dp) < margin || std::abs(dq) < margin || n.norm() < 1e-3)
            continue;
        bool expected = false;
        if ((dp > 0) != (dq > 0))
        {
            const Vec3 x = p + dp / (dp - dq) * (q - p);
            const double u = (b - x).cross(c - x).dot(n) / n.squaredNorm();
            const double v = (c - x).cross(a - x).dot(n) / n.squaredNorm();
            const double w = 1.0 - u - v;
            if (std::min({std::abs(u), std::abs(v), std::abs(w)}) < 1e-6)
                continue;
            expected = u > 0 && v > 0 && w > 0;
        }
        ++tested;
        hits += expected;
        ASSERT_EQ(segment_intersects_triangle(p, q, a, b, c), expected) << i;
    }
    EXPECT_GT(tested, 15000);
    EXPECT_GT(hits, 1000);
}

} // namespace
} // namespace zomeify

namespace zomeify {
namespace {

TEST(GeomClearance, RulesUseTheMinimaOfClearanceRules)
{
    const Vec3 o(0, 0, 0);
    EXPECT_TRUE(balls_clash(o, Vec3(kMinBallBall - 1e-9, 0, 0)));
    EXPECT_FALSE(balls_clash(o, Vec3(kMinBallBall + 1e-9, 0, 0)));
    const Vec3 s0(-1, 0, 0), s1(1, 0, 0);
    EXPECT_TRUE(ball_strut_clash(Vec3(0.3, kMinBallStrut - 1e-9, 0), s0, s1));
    EXPECT_FALSE(ball_strut_clash(Vec3(0.3, kMinBallStrut + 1e-9, 0), s0, s1));
    EXPECT_FALSE(ball_strut_clash(Vec3(1 + kMinBallStrut + 1e-9, 0, 0), s0, s1)); // beyond an end
    EXPECT_TRUE(struts_clash(s0, s1, Vec3(0, -1, kMinStrutStrut - 1e-9), Vec3(0, 1, kMinStrutStrut - 1e-9)));
    EXPECT_FALSE(struts_clash(s0, s1, Vec3(0, -1, kMinStrutStrut + 1e-9), Vec3(0, 1, kMinStrutStrut + 1e-9)));
    // A quad as its two canonical triangles; a strut through the shared diagonal meets it.
    const std::array<std::array<Vec3, 3>, 2> quad{
        {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0)}, {Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}}};
    EXPECT_TRUE(strut_face_clash(Vec3(0.5, 0.5, -1), Vec3(0.5, 0.5, 1), quad));
    EXPECT_TRUE(strut_face_clash(Vec3(0.2, 0.7, -1), Vec3(0.2, 0.7, 1), quad));
    EXPECT_FALSE(strut_face_clash(Vec3(1.2, 0.7, -1), Vec3(1.2, 0.7, 1), quad));
    EXPECT_FALSE(strut_face_clash(Vec3(0.2, 0.7, -1), Vec3(0.2, 0.7, 1), std::span(quad).first(1)));
}

} // namespace
} // namespace zomeify
