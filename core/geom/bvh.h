#pragma once
//! \file bvh.h
//! Bounding volume hierarchy over the triangles of the input surface (design §3.7): binned SAH,
//! built in O(n log n), flattened into compact two-wide nodes. Immutable once built, so any number
//! of threads may traverse it.

#include <array>
#include <cstdint>
#include <vector>

#include "core/geom/box3.h"
#include "core/geom/triangle_mesh.h"

namespace zomeify {

//! Build parameters. The defaults suit closest-point queries on meshes of 1k-1M triangles.
struct BvhOptions
{
    int bins = 16;         //!< SAH bins per axis (2..64)
    int max_leaf_size = 4; //!< at most this many primitives per leaf (1..4)
};

//! One flattened node: the boxes of its two children, stored per axis so both children are
//! tested together, in float rounded outward (and padded, see Bvh) so box distances are lower
//! bounds. Child i is an inner node `child[i]` when count[i] == 0, otherwise a leaf holding
//! primitives order[child[i]] .. order[child[i] + count[i] - 1]. An unused child (root of a
//! one-leaf tree) has count 0, child kInvalid and an empty box. Coordinates are relative to
//! Bvh::origin(), which keeps float precision where the primitives are. 64 bytes: one cache line.
struct alignas(64) BvhNode
{
    static constexpr uint32_t kInvalid = 0xffffffffu;

    std::array<float, 2> min_x, min_y, min_z;
    std::array<float, 2> max_x, max_y, max_z;
    std::array<uint32_t, 2> child;
    std::array<uint32_t, 2> count;
};

//! The hierarchy over a set of primitives given by their boxes.
class Bvh
{
public:
    //! Longest root-to-leaf path that a build can produce (traversal stacks use this size).
    static constexpr int kMaxDepth = 96;

    //! Builds over `boxes` (one per primitive; must not be empty). Binned SAH on the centroids;
    //! below depth 48 of a pathological input it switches to median splits, bounding the depth.
    //! Child boxes are padded by 1e-6 times the largest extent of the whole box, which keeps
    //! float box distances below the true ones for queries near the primitives (traversals add a
    //! relative slack of 1e-6 for the rounding of far queries).
    explicit Bvh(const std::vector<Box3>& boxes, const BvhOptions& options = {});

    const std::vector<BvhNode>& nodes() const { return nodes_; }
    //! Primitive indices in leaf order.
    const std::vector<uint32_t>& order() const { return order_; }
    //! Box of everything.
    const Box3& bounds() const { return bounds_; }
    //! Centre of bounds(): node boxes are stored relative to it.
    const Vec3& origin() const { return origin_; }
    //! Number of levels of inner nodes on the longest path (1 for a single node).
    int depth() const { return depth_; }
    size_t leaf_count() const { return leaves_; }

private:
    std::vector<BvhNode> nodes_;
    std::vector<uint32_t> order_;
    Box3 bounds_;
    Vec3 origin_ = Vec3::Zero();
    int depth_ = 0;
    size_t leaves_ = 0;
};

//! The box of every triangle of `mesh`, in triangle order.
std::vector<Box3> triangle_boxes(const TriangleMesh& mesh);

} // namespace zomeify
