#include "core/geom/bvh.h"

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"

namespace zomeify {
namespace {

// Past this depth the input defeats the SAH (e.g. many coincident centroids); median splits
// then halve every range, so the depth stays below Bvh::kMaxDepth for any 32-bit count.
constexpr int kMedianSplitDepth = 48;

float round_down(double x)
{
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x)
    {
        f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    }
    return f;
}

float round_up(double x)
{
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x)
    {
        f = std::nextafter(f, std::numeric_limits<float>::infinity());
    }
    return f;
}

class Builder
{
public:
    Builder(const std::vector<Box3>& boxes, const BvhOptions& options, std::vector<BvhNode>& nodes,
            std::vector<uint32_t>& order)
        : boxes_(boxes), nodes_(nodes), order_(order), bins_(std::clamp(options.bins, 2, 64)),
          max_leaf_(static_cast<uint32_t>(std::clamp(options.max_leaf_size, 1, 4)))
    {
        centroids_.reserve(boxes.size());
        for (const Box3& b : boxes)
        {
            centroids_.push_back(b.center());
        }
    }

    void build(const Vec3& origin, double pad)
    {
        origin_ = origin;
        pad_ = pad;
        const auto n = static_cast<uint32_t>(boxes_.size());
        nodes_.reserve(2 * (n / max_leaf_) + 2);
        nodes_.emplace_back();
        if (n <= max_leaf_)
        {
            set_child(0, 0, range_box(0, n), 0, n);
            set_empty_child(0, 1);
            leaves_ = 1;
            depth_ = 1;
            return;
        }
        build_node(0, 0, n, 1);
    }

    int depth() const { return depth_; }
    size_t leaves() const { return leaves_; }

private:
    // Splits [begin, end) (more than max_leaf_ primitives) under node `index`.
    void build_node(uint32_t index, uint32_t begin, uint32_t end, int depth)
    {
        depth_ = std::max(depth_, depth);
        const uint32_t mid = split(begin, end, depth);
        const uint32_t ranges[2][2] = {{begin, mid}, {mid, end}};
        for (int side = 0; side < 2; ++side)
        {
            const uint32_t b = ranges[side][0];
            const uint32_t e = ranges[side][1];
            const Box3 box = range_box(b, e);
            if (e - b <= max_leaf_)
            {
                set_child(index, side, box, b, e - b);
                ++leaves_;
            }
            else
            {
                const auto child = static_cast<uint32_t>(nodes_.size());
                nodes_.emplace_back();
                set_child(index, side, box, child, 0);
                build_node(child, b, e, depth + 1);
            }
        }
    }

    // Returns the split position; both sides are non-empty.
    uint32_t split(uint32_t begin, uint32_t end, int depth)
    {
        Box3 cbox;
        for (uint32_t i = begin; i < end; ++i)
        {
            cbox.extend(centroids_[order_[i]]);
        }
        const Vec3 extent = cbox.extent();
        int axis = 0;
        extent.maxCoeff(&axis);
        if (!(extent[axis] > 0.0))
        {
            return begin + (end - begin) / 2; // all centroids coincide: any halving is as good
        }
        if (depth < kMedianSplitDepth)
        {
            const uint32_t mid = sah_split(begin, end, cbox);
            if (mid > begin && mid < end)
            {
                return mid;
            }
        }
        const uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                         [&](uint32_t x, uint32_t y) { return centroids_[x][axis] < centroids_[y][axis]; });
        return mid;
    }

    // Binned SAH over all three axes; partitions the range and returns the split, or `begin`
    // if no binned split separates the centroids.
    uint32_t sah_split(uint32_t begin, uint32_t end, const Box3& cbox)
    {
        struct Bin
        {
            Box3 box;
            uint32_t count = 0;
        };
        double best_cost = std::numeric_limits<double>::infinity();
        int best_axis = -1;
        int best_bin = 0;
        std::array<Bin, 64> bins;
        std::array<double, 64> right_cost;
        for (int axis = 0; axis < 3; ++axis)
        {
            const double lo = cbox.min[axis];
            const double ext = cbox.max[axis] - lo;
            if (!(ext > 0.0))
            {
                continue;
            }
            const double scale = bins_ / ext;
            std::fill(bins.begin(), bins.begin() + bins_, Bin{});
            for (uint32_t i = begin; i < end; ++i)
            {
                const uint32_t prim = order_[i];
                Bin& bin = bins[bin_of(centroids_[prim][axis], lo, scale)];
                bin.box.extend(boxes_[prim]);
                ++bin.count;
            }
            // Sweep from the right to get the right-hand cost of every split, then from the left.
            Box3 acc;
            uint32_t count = 0;
            for (int k = bins_ - 1; k > 0; --k)
            {
                acc.extend(bins[k].box);
                count += bins[k].count;
                right_cost[k] = count == 0 ? 0.0 : acc.half_area() * count;
            }
            acc = Box3{};
            count = 0;
            for (int k = 1; k < bins_; ++k)
            {
                acc.extend(bins[k - 1].box);
                count += bins[k - 1].count;
                const double cost = (count == 0 ? 0.0 : acc.half_area() * count) + right_cost[k];
                if (count > 0 && count < end - begin && cost < best_cost)
                {
                    best_cost = cost;
                    best_axis = axis;
                    best_bin = k;
                }
            }
        }
        if (best_axis < 0)
        {
            return begin;
        }
        const double lo = cbox.min[best_axis];
        const double scale = bins_ / (cbox.max[best_axis] - lo);
        const auto it = std::partition(order_.begin() + begin, order_.begin() + end, [&](uint32_t prim) {
            return bin_of(centroids_[prim][best_axis], lo, scale) < best_bin;
        });
        return static_cast<uint32_t>(it - order_.begin());
    }

    int bin_of(double c, double lo, double scale) const
    {
        const int k = static_cast<int>((c - lo) * scale);
        return std::clamp(k, 0, bins_ - 1);
    }

    Box3 range_box(uint32_t begin, uint32_t end) const
    {
        Box3 box;
        for (uint32_t i = begin; i < end; ++i)
        {
            box.extend(boxes_[order_[i]]);
        }
        return box;
    }

    void set_child(uint32_t index, int side, const Box3& box, uint32_t child, uint32_t count)
    {
        BvhNode& node = nodes_[index];
        node.min_x[side] = round_down(box.min.x() - origin_.x() - pad_);
        node.min_y[side] = round_down(box.min.y() - origin_.y() - pad_);
        node.min_z[side] = round_down(box.min.z() - origin_.z() - pad_);
        node.max_x[side] = round_up(box.max.x() - origin_.x() + pad_);
        node.max_y[side] = round_up(box.max.y() - origin_.y() + pad_);
        node.max_z[side] = round_up(box.max.z() - origin_.z() + pad_);
        node.child[side] = child;
        node.count[side] = count;
    }

    void set_empty_child(uint32_t index, int side)
    {
        BvhNode& node = nodes_[index];
        const float inf = std::numeric_limits<float>::infinity();
        node.min_x[side] = node.min_y[side] = node.min_z[side] = inf;
        node.max_x[side] = node.max_y[side] = node.max_z[side] = -inf;
        node.child[side] = BvhNode::kInvalid;
        node.count[side] = 0;
    }

    const std::vector<Box3>& boxes_;
    std::vector<Vec3> centroids_;
    std::vector<BvhNode>& nodes_;
    std::vector<uint32_t>& order_;
    const int bins_;
    const uint32_t max_leaf_;
    Vec3 origin_ = Vec3::Zero();
    double pad_ = 0.0;
    int depth_ = 0;
    size_t leaves_ = 0;
};

} // namespace

Bvh::Bvh(const std::vector<Box3>& boxes, const BvhOptions& options)
{
    if (boxes.empty())
    {
        throw InvalidInputError("BVH: no primitives");
    }
    if (boxes.size() >= BvhNode::kInvalid)
    {
        throw InvalidInputError("BVH: too many primitives");
    }
    for (const Box3& b : boxes)
    {
        if (!b.min.allFinite() || !b.max.allFinite() || b.empty())
        {
            throw InvalidInputError("BVH: a primitive has a non-finite or empty box");
        }
        bounds_.extend(b);
    }
    order_.resize(boxes.size());
    for (uint32_t i = 0; i < order_.size(); ++i)
    {
        order_[i] = i;
    }
    origin_ = bounds_.center();
    Builder builder(boxes, options, nodes_, order_);
    builder.build(origin_, 1e-6 * std::max(bounds_.extent().maxCoeff(), std::numeric_limits<double>::min()));
    depth_ = builder.depth();
    leaves_ = builder.leaves();
}

std::vector<Box3> triangle_boxes(const TriangleMesh& mesh)
{
    std::vector<Box3> boxes(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
    {
        for (const uint32_t v : mesh.triangles[t])
        {
            boxes[t].extend(mesh.positions[v]);
        }
    }
    return boxes;
}

} // namespace zomeify
