#include "core/geom/wide_bvh.h"

#include <algorithm>
#include <limits>

#include "core/base/errors.h"

namespace zomeify {
namespace {

// A child of a binary node, with its (float, padded) box from the parent.
struct Ref
{
    uint32_t child;
    uint32_t count;
    Box3 box;
};

Ref child_ref(const BvhNode& node, int side)
{
    Box3 box;
    box.min = Vec3(node.min_x[side], node.min_y[side], node.min_z[side]);
    box.max = Vec3(node.max_x[side], node.max_y[side], node.max_z[side]);
    return {node.child[side], node.count[side], box};
}

class Collapser
{
public:
    Collapser(const Bvh& bvh, std::vector<WideBvhNode>& out, std::vector<WideBvhLeaf>& leaves)
        : bvh_(bvh), out_(out), leaves_(leaves)
    {
    }

    int depth() const { return depth_; }

    // Emits the wide node for the children of binary node `index`; returns its index.
    uint32_t emit(uint32_t index, int depth)
    {
        depth_ = std::max(depth_, depth);
        const BvhNode& node = bvh_.nodes()[index];
        std::vector<Ref> refs;
        for (int side = 0; side < 2; ++side)
        {
            if (node.child[side] != BvhNode::kInvalid)
            {
                refs.push_back(child_ref(node, side));
            }
        }
        // Pull up the children of the largest inner child until there are four.
        while (refs.size() < 4)
        {
            int pick = -1;
            double area = -1.0;
            for (int i = 0; i < static_cast<int>(refs.size()); ++i)
            {
                if (refs[i].count == 0 && refs[i].box.half_area() > area)
                {
                    area = refs[i].box.half_area();
                    pick = i;
                }
            }
            if (pick < 0)
            {
                break;
            }
            const BvhNode& inner = bvh_.nodes()[refs[pick].child];
            refs.erase(refs.begin() + pick);
            for (int side = 0; side < 2; ++side)
            {
                if (inner.child[side] != BvhNode::kInvalid)
                {
                    refs.push_back(child_ref(inner, side));
                }
            }
        }

        const auto self = static_cast<uint32_t>(out_.size());
        out_.emplace_back();
        set_boxes(self, refs);
        for (size_t j = 0; j < refs.size(); ++j)
        {
            uint32_t c = 0;
            if (refs[j].count > 0)
            {
                c = WideBvhNode::make_leaf(static_cast<uint32_t>(leaves_.size()), refs[j].count);
                leaves_.push_back({refs[j].child, refs[j].count});
            }
            else
            {
                c = emit(refs[j].child, depth + 1);
            }
            out_[self].child[j] = c; // after emit: out_ may have grown
        }
        return self;
    }

private:
    void set_boxes(uint32_t self, const std::vector<Ref>& refs)
    {
        WideBvhNode& node = out_[self];
        const float inf = std::numeric_limits<float>::infinity();
        for (int j = 0; j < 4; ++j)
        {
            const bool used = j < static_cast<int>(refs.size());
            // Binary-tree boxes are floats already: the conversions below are exact.
            node.min_x[j] = used ? static_cast<float>(refs[j].box.min.x()) : inf;
            node.min_y[j] = used ? static_cast<float>(refs[j].box.min.y()) : inf;
            node.min_z[j] = used ? static_cast<float>(refs[j].box.min.z()) : inf;
            node.max_x[j] = used ? static_cast<float>(refs[j].box.max.x()) : -inf;
            node.max_y[j] = used ? static_cast<float>(refs[j].box.max.y()) : -inf;
            node.max_z[j] = used ? static_cast<float>(refs[j].box.max.z()) : -inf;
            node.child[j] = WideBvhNode::kEmpty;
        }
    }

    const Bvh& bvh_;
    std::vector<WideBvhNode>& out_;
    std::vector<WideBvhLeaf>& leaves_;
    int depth_ = 0;
};

} // namespace

WideBvh::WideBvh(const Bvh& bvh)
{
    if (bvh.order().size() >= WideBvhNode::kMaxLeaves)
    {
        throw InvalidInputError("BVH: too many primitives for the wide layout");
    }
    nodes_.reserve(bvh.nodes().size() / 2 + 1);
    leaves_.reserve(bvh.leaf_count());
    Collapser collapser(bvh, nodes_, leaves_);
    collapser.emit(0, 1);
    depth_ = collapser.depth();
}

Box3 WideBvh::child_box(const WideBvhNode& node, int j)
{
    Box3 box;
    box.min = Vec3(node.min_x[j], node.min_y[j], node.min_z[j]);
    box.max = Vec3(node.max_x[j], node.max_y[j], node.max_z[j]);
    return box;
}

} // namespace zomeify
