// Triangle / box overlap: hand-made contact cases and a randomized comparison with clipping.

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/voxel/tri_box.h"

using namespace zomeify;

namespace {

// Reference: clip the triangle by the six planes of the closed box [lo, hi] (Sutherland–Hodgman);
// it meets the box iff something is left.
bool clipped_nonempty(std::vector<Vec3> poly, const Vec3& lo, const Vec3& hi)
{
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
        {
            auto inside = [&](const Vec3& p) { return side ? p[axis] <= hi[axis] : p[axis] >= lo[axis]; };
            const double bound = side ? hi[axis] : lo[axis];
            std::vector<Vec3> out;
            for (size_t i = 0; i < poly.size(); ++i)
            {
                const Vec3& p = poly[i];
                const Vec3& q = poly[(i + 1) % poly.size()];
                if (inside(p))
                    out.push_back(p);
                if (inside(p) != inside(q))
                    out.push_back(p + (q - p) * ((bound - p[axis]) / (q[axis] - p[axis])));
            }
            poly = std::move(out);
            if (poly.empty())
                return false;
        }
    return true;
}

} // namespace

TEST(VoxelTriBox, ContactCases)
{
    const Vec3 c(0, 0, 0), h(1, 1, 1);
    // Inside, crossing, far.
    EXPECT_TRUE(triangle_box_overlap(c, h, {0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, BoxContact::Open));
    EXPECT_TRUE(triangle_box_overlap(c, h, {-5, 0, 0}, {5, 0.1, 0}, {0, 5, 0.2}, BoxContact::Open));
    EXPECT_FALSE(triangle_box_overlap(c, h, {3, 3, 3}, {4, 3, 3}, {3, 4, 3}, BoxContact::Closed));
    // Lying in the plane of a face: touches the closed box, misses the open one.
    EXPECT_TRUE(triangle_box_overlap(c, h, {1, -0.5, -0.5}, {1, 0.5, -0.5}, {1, 0, 0.5}, BoxContact::Closed));
    EXPECT_FALSE(triangle_box_overlap(c, h, {1, -0.5, -0.5}, {1, 0.5, -0.5}, {1, 0, 0.5}, BoxContact::Open));
    // Touching one corner only.
    EXPECT_TRUE(triangle_box_overlap(c, h, {1, 1, 1}, {2, 1, 1}, {1, 2, 1}, BoxContact::Closed));
    EXPECT_FALSE(triangle_box_overlap(c, h, {1, 1, 1}, {2, 1, 1}, {1, 2, 1}, BoxContact::Open));
    // Cutting past a corner: only the triangle's normal separates (its plane x + y + z = 3.2).
    EXPECT_FALSE(triangle_box_overlap(c, h, {3.2, 0, 0}, {0, 3.2, 0}, {0, 0, 3.2}, BoxContact::Closed));
    EXPECT_TRUE(triangle_box_overlap(c, h, {2.9, 0, 0}, {0, 2.9, 0}, {0, 0, 2.9}, BoxContact::Open));
    // Past an edge of the box: only an edge × axis cross product separates.
    EXPECT_FALSE(triangle_box_overlap(c, h, {2.1, 0, -5}, {0, 2.1, -5}, {0, 2.1, 5}, BoxContact::Closed));
    EXPECT_TRUE(triangle_box_overlap(c, h, {1.9, 0, -5}, {0, 1.9, -5}, {0, 1.9, 5}, BoxContact::Open));
    // Degenerate triangle (a segment through the box).
    EXPECT_TRUE(triangle_box_overlap(c, h, {-2, 0, 0}, {2, 0, 0}, {0, 0, 0}, BoxContact::Open));
}

TEST(VoxelTriBox, AgreesWithClippingOnRandomTriangles)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    const Vec3 c(0.1, -0.2, 0.3), h(0.5, 0.7, 0.4);
    int hits = 0, misses = 0;
    for (int n = 0; n < 20000; ++n)
    {
        Vec3 p[3];
        for (auto& q : p)
        {
            const double x = u(rng), y = u(rng), z = u(rng);
            q = Vec3(x, y, z);
        }
        // Skip borderline cases, where rounding decides: require the same answer for a box a
        // little smaller and a little larger.
        const Vec3 eps = Vec3::Constant(1e-9);
        const bool small = clipped_nonempty({p[0], p[1], p[2]}, c - h + eps, c + h - eps);
        const bool large = clipped_nonempty({p[0], p[1], p[2]}, c - h - eps, c + h + eps);
        if (small != large)
            continue;
        EXPECT_EQ(triangle_box_overlap(c, h, p[0], p[1], p[2], BoxContact::Closed), small);
        EXPECT_EQ(triangle_box_overlap(c, h, p[0], p[1], p[2], BoxContact::Open), small);
        (small ? hits : misses)++;
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(misses, 1000);
}
