#pragma once
//! \file wide_bvh.h
//! A 4-wide copy of a Bvh, the form the closest-point search walks: a third of the binary tree's
//! nodes and half its depth, and the four child boxes of a node in structure-of-arrays form, so
//! their distances are computed together in vector registers.

#include <array>
#include <cstdint>
#include <vector>

#include "core/geom/bvh.h"

namespace zomeify {

//! Four child boxes (float, copied from the binary tree: rounded outward and padded, relative to
//! Bvh::origin()). A child is an inner node index, or a leaf (kLeafBit set): entry leaf_index() of
//! WideBvh::leaves(), holding leaf_count() primitives; or kEmpty (with an empty box). 128 bytes.
struct alignas(64) WideBvhNode
{
    static constexpr uint32_t kEmpty = 0xffffffffu;
    static constexpr uint32_t kLeafBit = 0x80000000u;
    //! Leaves hold up to 7 primitives and are numbered below 2^28.
    static constexpr uint32_t kMaxLeaves = 1u << 28;

    std::array<float, 4> min_x, min_y, min_z;
    std::array<float, 4> max_x, max_y, max_z;
    std::array<uint32_t, 4> child;

    static bool is_leaf(uint32_t c) { return c != kEmpty && (c & kLeafBit) != 0; }
    static uint32_t leaf_index(uint32_t c) { return c & (kMaxLeaves - 1); }
    static uint32_t leaf_count(uint32_t c) { return (c >> 28) & 7u; }
    static uint32_t make_leaf(uint32_t index, uint32_t count) { return kLeafBit | (count << 28) | index; }
};

//! A leaf's primitives: Bvh::order()[first .. first + count).
struct WideBvhLeaf
{
    uint32_t first;
    uint32_t count;
};

//! Built from a binary Bvh by pulling up grandchildren (largest box first) until each node has
//! four children. Leaves are numbered in depth-first order, so that data stored per leaf (the
//! projector's triangle blocks) lies near the data of neighbouring leaves. Immutable; shareable
//! between threads.
class WideBvh
{
public:
    //! Throws InvalidInputError above 2^28 primitives.
    explicit WideBvh(const Bvh& bvh);

    const std::vector<WideBvhNode>& nodes() const { return nodes_; }
    //! The binary tree's leaves, in depth-first order of the wide tree.
    const std::vector<WideBvhLeaf>& leaves() const { return leaves_; }
    //! Levels of inner nodes on the longest path.
    int depth() const { return depth_; }

    //! Child j's box of `node` (relative to Bvh::origin()).
    static Box3 child_box(const WideBvhNode& node, int j);

private:
    std::vector<WideBvhNode> nodes_;
    std::vector<WideBvhLeaf> leaves_;
    int depth_ = 0;
};

} // namespace zomeify
