#include "core/geom/bvh.h"
#include "core/geom/wide_bvh.h"

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/geom_fixtures.h"

namespace zomeify {
namespace {

bool float_box_contains(const BvhNode& node, int side, const Box3& absolute, const Vec3& origin)
{
    const Box3 box{absolute.min - origin, absolute.max - origin};
    return node.min_x[side] <= box.min.x() && node.min_y[side] <= box.min.y() && node.min_z[side] <= box.min.z() &&
           node.max_x[side] >= box.max.x() && node.max_y[side] >= box.max.y() && node.max_z[side] >= box.max.z();
}

// Walks the tree: every primitive in exactly one leaf, leaves small, child boxes enclose.
void check_structure(const Bvh& bvh, const std::vector<Box3>& boxes, int max_leaf)
{
    std::vector<int> seen(boxes.size(), 0);
    std::vector<std::pair<uint32_t, int>> pending{{0u, 1}};
    size_t leaves = 0;
    while (!pending.empty())
    {
        const auto [index, depth] = pending.back();
        pending.pop_back();
        ASSERT_LT(index, bvh.nodes().size());
        ASSERT_LE(depth, Bvh::kMaxDepth);
        const BvhNode& node = bvh.nodes()[index];
        for (int side = 0; side < 2; ++side)
        {
            if (node.child[side] == BvhNode::kInvalid)
            {
                EXPECT_EQ(index, 0u);
                continue;
            }
            if (node.count[side] == 0)
            {
                pending.push_back({node.child[side], depth + 1});
                continue;
            }
            ++leaves;
            EXPECT_LE(node.count[side], static_cast<uint32_t>(max_leaf));
            for (uint32_t k = node.child[side]; k < node.child[side] + node.count[side]; ++k)
            {
                const uint32_t prim = bvh.order()[k];
                ++seen[prim];
                EXPECT_TRUE(float_box_contains(node, side, boxes[prim], bvh.origin()));
            }
        }
    }
    EXPECT_EQ(leaves, bvh.leaf_count());
    for (size_t i = 0; i < seen.size(); ++i)
    {
        ASSERT_EQ(seen[i], 1) << "primitive " << i;
    }
}

// The 4-wide copy: the same leaves, every primitive once, boxes enclosing the primitives.
void check_wide(const Bvh& bvh, const std::vector<Box3>& boxes)
{
    const WideBvh wide(bvh);
    std::vector<int> seen(boxes.size(), 0);
    std::vector<uint32_t> pending{0u};
    size_t visited = 0;
    size_t leaves = 0;
    while (!pending.empty())
    {
        const uint32_t index = pending.back();
        pending.pop_back();
        ASSERT_LT(index, wide.nodes().size());
        ++visited;
        const WideBvhNode& node = wide.nodes()[index];
        for (int j = 0; j < 4; ++j)
        {
            const uint32_t c = node.child[j];
            if (c == WideBvhNode::kEmpty)
            {
                EXPECT_TRUE(WideBvh::child_box(node, j).empty());
                continue;
            }
            if (!WideBvhNode::is_leaf(c))
            {
                pending.push_back(c);
                continue;
            }
            const Box3 box = WideBvh::child_box(node, j);
            ASSERT_LT(WideBvhNode::leaf_index(c), wide.leaves().size());
            const WideBvhLeaf& leaf = wide.leaves()[WideBvhNode::leaf_index(c)];
            ASSERT_EQ(leaf.count, WideBvhNode::leaf_count(c));
            ++leaves;
            for (uint32_t k = leaf.first; k < leaf.first + leaf.count; ++k)
            {
                const uint32_t prim = bvh.order()[k];
                ++seen[prim];
                EXPECT_TRUE((box.min.array() <= (boxes[prim].min - bvh.origin()).array()).all());
                EXPECT_TRUE((box.max.array() >= (boxes[prim].max - bvh.origin()).array()).all());
            }
        }
    }
    EXPECT_EQ(visited, wide.nodes().size());
    EXPECT_EQ(leaves, wide.leaves().size());
    EXPECT_EQ(leaves, bvh.leaf_count());
    EXPECT_LE(wide.depth(), bvh.depth());
    for (size_t i = 0; i < seen.size(); ++i)
    {
        ASSERT_EQ(seen[i], 1) << "primitive " << i;
    }
}

TEST(GeomBvh, EveryTriangleInExactlyOneSmallLeaf)
{
    for (const auto& [name, mesh] : test::procedural_surfaces())
    {
        SCOPED_TRACE(name);
        const std::vector<Box3> boxes = triangle_boxes(mesh);
        const Bvh bvh(boxes);
        check_structure(bvh, boxes, 4);
        check_wide(bvh, boxes);
        EXPECT_LT(bvh.depth(), 40);
    }
}

TEST(GeomBvh, LeafSizeOptionAndTinyInputs)
{
    const TriangleMesh mesh = test::make_icosphere(1.0, 2);
    const std::vector<Box3> boxes = triangle_boxes(mesh);
    check_structure(Bvh(boxes, {8, 1}), boxes, 1);
    for (size_t n = 1; n <= 9; ++n)
    {
        const std::vector<Box3> few(boxes.begin(), boxes.begin() + static_cast<std::ptrdiff_t>(n));
        check_structure(Bvh(few), few, 4);
        check_wide(Bvh(few), few);
    }
}

TEST(GeomBvh, CoincidentCentroidsKeepTheDepthBounded)
{
    std::vector<Box3> boxes(5000);
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (Box3& b : boxes)
    {
        const double r = u(rng);
        b.extend(Vec3(-r, -r, -r));
        b.extend(Vec3(r, r, r));
    }
    const Bvh bvh(boxes);
    check_structure(bvh, boxes, 4);
    check_wide(bvh, boxes);
    EXPECT_LE(bvh.depth(), 14);
}

TEST(GeomBvh, RejectsEmptyAndNonFiniteInput)
{
    EXPECT_ANY_THROW(Bvh(std::vector<Box3>{}));
    std::vector<Box3> boxes(1);
    boxes[0].extend(Vec3(0, 0, std::numeric_limits<double>::quiet_NaN()));
    EXPECT_ANY_THROW(Bvh{boxes});
}

} // namespace
} // namespace zomeify
