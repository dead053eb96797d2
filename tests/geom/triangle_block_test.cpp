// The float distance estimate of a TriangleBlock stays within its stated slack of the exact
// distance, for every lane, on well-shaped, sliver, needle, degenerate and tiny triangles, for
// points on, near (inside and outside each edge) and far from them. The closest-point search is
// exact only if this holds.
#include "core/geom/triangle_block.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tests/geom/geom_reference.h"

namespace zomeify {
namespace {

// A block of the (1..4) triangles of `mesh` relative to `origin`, with the sliver width a
// projector would use.
struct BlockCase
{
    TriangleMesh mesh;
    Vec3 origin = Vec3::Zero();

    double half_extent() const
    {
        double h = 0.0;
        for (const Vec3& v : mesh.positions)
        {
            h = std::max(h, (v - origin).cwiseAbs().maxCoeff());
        }
        return h;
    }
    TriangleBlock block() const
    {
        const uint32_t ids[4] = {0, 1, 2, 3};
        return make_triangle_block(mesh, ids, static_cast<uint32_t>(mesh.triangles.size()), origin,
                                   TriangleBlockTolerance::kSliverWidth * half_extent());
    }
};

// Every lane's estimate against the exact distance (lanes past the count repeat triangle 0).
void expect_within_slack(const BlockCase& c, const TriangleBlock& block, const Vec3& p)
{
    const Vec3 rel = p - c.origin;
    const double magnitude = rel.cwiseAbs().maxCoeff() + c.half_extent();
    const std::array<float, 4> estimate = estimate_block_distances_squared(block, rel, magnitude);
    const auto count = static_cast<int>(c.mesh.triangles.size());
    for (int lane = 0; lane < 4; ++lane)
    {
        const auto& t = c.mesh.triangles[static_cast<size_t>(lane < count ? lane : 0)];
        const double exact = test::reference_triangle_distance_squared(p, c.mesh.positions[t[0]],
                                                                       c.mesh.positions[t[1]], c.mesh.positions[t[2]]);
        ASSERT_TRUE(std::isfinite(estimate[lane]));
        ASSERT_NEAR(std::sqrt(static_cast<double>(estimate[lane])), std::sqrt(exact),
                    TriangleBlockTolerance::kSlack * magnitude)
            << "lane " << lane << ", triangle " << (lane < count ? lane : 0) << " = "
            << c.mesh.positions[t[0]].transpose() << " / " << c.mesh.positions[t[1]].transpose() << " / "
            << c.mesh.positions[t[2]].transpose() << ", p = " << std::setprecision(17) << p.transpose();
    }
}

// Points that stress the estimate: corners, edge points pushed slightly inside and outside in the
// plane and off it, points over the face, and random points near and far.
std::vector<Vec3> probe_points(const Vec3& a, const Vec3& b, const Vec3& c, double scale, std::mt19937& rng)
{
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> g(0.0, 1.0);
    Vec3 n = (b - a).cross(c - a);
    n = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::UnitZ();
    const Vec3 centre = (a + b + c) / 3.0;
    std::vector<Vec3> out = {a, b, c, (a + b) / 2.0, (b + c) / 2.0, (c + a) / 2.0, centre};
    const Vec3 corners[3] = {a, b, c};
    for (int e = 0; e < 3; ++e)
    {
        const Vec3& s = corners[e];
        const Vec3& t = corners[(e + 1) % 3];
        for (const double offset : {1e-9, 1e-7, 1e-5, 1e-3})
        {
            const Vec3 on = s + u(rng) * (t - s);
            Vec3 inward = centre - on;
            inward -= inward.dot(n) * n;
            inward = inward.norm() > 0.0 ? Vec3(inward.normalized()) : Vec3::UnitX();
            for (const double side : {-1.0, 1.0})
            {
                for (const double height : {0.0, 1e-6, 0.01, 0.5})
                {
                    out.push_back(on + side * offset * scale * inward + height * scale * n);
                }
            }
        }
    }
    for (int i = 0; i < 40; ++i)
    {
        const double reach = scale * std::pow(10.0, -6.0 + 8.0 * u(rng));
        out.push_back(centre + reach * Vec3(g(rng), g(rng), g(rng)));
    }
    return out;
}

void check_triangles(const BlockCase& c, std::mt19937& rng)
{
    const TriangleBlock block = c.block();
    const double scale = std::max(c.half_extent(), 1e-300);
    for (const auto& t : c.mesh.triangles)
    {
        for (const Vec3& p :
             probe_points(c.mesh.positions[t[0]], c.mesh.positions[t[1]], c.mesh.positions[t[2]], scale, rng))
        {
            expect_within_slack(c, block, p);
        }
    }
}

BlockCase random_case(std::mt19937& rng, const Vec3& origin, double size, int count)
{
    std::uniform_real_distribution<double> u(-size, size);
    BlockCase c;
    c.origin = origin;
    for (int t = 0; t < count; ++t)
    {
        const auto first = static_cast<uint32_t>(c.mesh.positions.size());
        for (int k = 0; k < 3; ++k)
        {
            c.mesh.positions.push_back(origin + Vec3(u(rng), u(rng), u(rng)));
        }
        c.mesh.triangles.push_back({first, first + 1, first + 2});
    }
    return c;
}

TEST(GeomTriangleBlock, EstimateWithinSlackOnRandomTriangles)
{
    std::mt19937 rng(41);
    for (int i = 0; i < 200; ++i)
    {
        // Origins far from zero, as with real meshes in their own units; 1 to 4 lanes in use.
        const Vec3 origin(1e3 * (i % 7), -250.0 * (i % 5), 0.5);
        check_triangles(random_case(rng, origin, std::pow(10.0, (i % 9) - 4), 1 + i % 4), rng);
    }
}

TEST(GeomTriangleBlock, EstimateWithinSlackOnSliversNeedlesAndDegenerateTriangles)
{
    std::mt19937 rng(42);
    BlockCase c;
    c.origin = Vec3(10.0, -20.0, 30.0);
    const Vec3 o = c.origin;
    c.mesh.positions = {
        o + Vec3(-1, -1, 0),
        o + Vec3(1, -1, 0),
        o + Vec3(0, -1 + 1e-9, 0.5), // needle, width 1e-9
        o + Vec3(-1, 0, 0),
        o + Vec3(1, 0, 1e-5),
        o + Vec3(0, 1e-6, 0), // sliver, width ~1e-6
        o + Vec3(0.2, 0.2, 0.2),
        o + Vec3(0.4, 0.4, 0.4),
        o + Vec3(0.9, 0.9, 0.9), // collinear: zero area
        o + Vec3(0.5, -0.5, 0.25),
        o + Vec3(0.5, -0.5, 0.25),
        o + Vec3(0.5, -0.5, 0.25), // one point
        o + Vec3(-0.3, 0.6, -0.2),
        o + Vec3(-0.3, 0.6, -0.2),
        o + Vec3(0.3, 0.7, 0.9), // repeated corner
        o + Vec3(0.1, 0.1, 0.1),
        o + Vec3(0.1 + 1e-7, 0.1, 0.1),
        o + Vec3(0.1, 0.1 + 1e-7, 0.1), // tiny
        o + Vec3(-1, 1, -1),
        o + Vec3(1, 1, 1),
        o + Vec3(-1, -1, 1), // large, well shaped
    };
    for (uint32_t t = 0; t < 7; ++t)
    {
        c.mesh.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    }
    // Blocks of four, so that every triangle is checked in several lanes and next to the others.
    for (uint32_t start = 0; start < 7; ++start)
    {
        BlockCase four;
        four.origin = c.origin;
        four.mesh.positions = c.mesh.positions;
        for (uint32_t k = 0; k < 4; ++k)
        {
            four.mesh.triangles.push_back(c.mesh.triangles[(start + k) % 7]);
        }
        check_triangles(four, rng);
    }
}

TEST(GeomTriangleBlock, UnusedLanesRepeatTheFirstTriangle)
{
    std::mt19937 rng(43);
    const BlockCase c = random_case(rng, Vec3(1, 2, 3), 1.0, 2);
    const TriangleBlock block = c.block();
    for (int lane = 2; lane < 4; ++lane)
    {
        EXPECT_EQ(block.ax[lane], block.ax[0]);
        EXPECT_EQ(block.acz[lane], block.acz[0]);
        EXPECT_EQ(block.nx[lane], block.nx[0]);
    }
    EXPECT_NE(block.ax[1], block.ax[0]);
}

} // namespace
} // namespace zomeify
