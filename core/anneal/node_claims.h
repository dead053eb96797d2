#pragma once
//! \file node_claims.h
//! Tag regions (paper §5.3, design.md §3.6): before a proposal reads anything about a node (its
//! position, its star, the elements around it) it claims the node. A claimed node belongs to one
//! thread until released, and every commit only changes elements whose nodes its thread holds, so
//! what a thread has claimed cannot change under it: validity and ΔE need no global lock.
//!
//! NodeTags is the shared table (one atomic owner word per node index, each on its own cache line, sized to the
//! capacity the engine reserves before starting threads). Claims is one proposal's set of held nodes. Single-threaded
//! use passes no table: every claim succeeds and nothing is shared.

#include <atomic>
#include <cstdint>
#include <memory>

#include "core/anneal/fixed_list.h"
#include "core/mesh/handles.h"

namespace zomeify {

class NodeTags
{
public:
    //! Room for node indices [0, capacity).
    explicit NodeTags(size_t capacity);
    size_t capacity() const noexcept { return capacity_; }
    //! Takes v for `owner` (≥ 1) if v is free or already owner's; false if another owner holds it
    //! or v is beyond the capacity.
    bool try_take(Vertex v, uint32_t owner) noexcept;
    //! Frees v if owner holds it.
    void release(Vertex v, uint32_t owner) noexcept;
    //! The owner of v (0 = free).
    uint32_t owner(Vertex v) const noexcept;

private:
    // One cache line per node: threads claim and release nodes all the time, and with packed words
    // every claim would also invalidate the line holding 15 other nodes' words in the other cores.
    struct alignas(64) Owner
    {
        std::atomic<uint32_t> word{0};
    };
    size_t capacity_;
    std::unique_ptr<Owner[]> owners_;
};

class Claims
{
public:
    static constexpr size_t kMaxNodes = 160;

    //! tags == nullptr: single-threaded, every take() succeeds. owner ≥ 1 identifies the thread.
    explicit Claims(NodeTags* tags = nullptr, uint32_t owner = 1) noexcept : tags_(tags), owner_(owner) {}
    Claims(const Claims&) = delete;
    Claims& operator=(const Claims&) = delete;
    ~Claims() { release_all(); }

    //! Claims v; true if this proposal now holds it (or already did). False if another thread
    //! holds it or the list is full: the proposal must then be abandoned.
    bool take(Vertex v) noexcept;
    //! Whether v is held by this proposal (O(held)).
    bool holds(Vertex v) const noexcept;
    //! Releases every held node (after the commit, or when the proposal is dropped).
    void release_all() noexcept;
    const FixedList<Vertex, kMaxNodes>& held() const noexcept { return held_; }
    bool shared() const noexcept { return tags_ != nullptr; }

private:
    NodeTags* tags_;
    uint32_t owner_;
    FixedList<Vertex, kMaxNodes> held_;
};

} // namespace zomeify
