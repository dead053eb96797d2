#pragma once
//! \file position_index.h
//! PositionIndex: the exact position → node map behind "no two nodes at one position". Open
//! addressing with linear probing in a power-of-two table at most half full, so a lookup is one
//! hash and, typically, one or two cache lines.
//!
//! Concurrency: one writer (the thread committing, under the annealer's lock) and any number of
//! readers may run together, provided the writer does not rehash: check has_capacity_for() (or
//! reserve()) before a parallel phase. A slot's key is written once, before its value is published
//! with release order, and is never rewritten until the next rehash: erase leaves a tombstone and
//! insert never reuses one. A concurrent find is therefore memory-safe but may be stale by one
//! commit; re-check under the lock before acting on it.

#include <atomic>
#include <cstddef>
#include <vector>

#include "core/mesh/handles.h"
#include "core/zome/zvec.h"

namespace zomeify {

class PositionIndex
{
public:
    //! The vertex at p, or invalid.
    Vertex find(const ZVec& p) const
    {
        // Reads only the table and the mask, which change in rehash alone (never concurrently).
        if (table_.empty())
            return {};
        for (size_t i = ZVecHash()(p) & mask_;; i = (i + 1) & mask_)
        {
            const Entry& e = table_[i];
            const MeshIndex value = e.value.load(std::memory_order_acquire);
            if (value == kEmpty)
                return {};
            if (value != kTombstone && e.key == p)
                return Vertex(value);
        }
    }
    bool contains(const ZVec& p) const { return find(p).is_valid(); }
    //! Adds p → v; returns false (and changes nothing) if p is already present.
    bool insert(const ZVec& p, Vertex v);
    //! Removes p; returns false if it was not present.
    bool erase(const ZVec& p);
    //! Makes room for n entries without a rehash.
    void reserve(size_t n);
    //! Whether n more inserts fit without a rehash.
    bool has_capacity_for(size_t n) const { return 2 * (used_ + n) <= table_.size(); }
    void clear();
    size_t size() const { return size_; }
    //! Calls f(position, vertex) for every entry (in table order).
    template <class F>
    void for_each(F&& f) const
    {
        for (const Entry& e : table_)
        {
            const MeshIndex value = e.value.load(std::memory_order_acquire);
            if (value != kEmpty && value != kTombstone)
                f(e.key, Vertex(value));
        }
    }

private:
    static constexpr MeshIndex kEmpty = kInvalidMeshIndex;
    static constexpr MeshIndex kTombstone = kInvalidMeshIndex - 1;
    struct Entry
    {
        ZVec key;
        std::atomic<MeshIndex> value{kEmpty};

        Entry() = default;
        // Copies happen only in rehash and in copies of the whole mesh, never concurrently.
        Entry(const Entry& o) : key(o.key), value(o.value.load(std::memory_order_relaxed)) {}
        Entry& operator=(const Entry& o)
        {
            key = o.key;
            value.store(o.value.load(std::memory_order_relaxed), std::memory_order_relaxed);
            return *this;
        }
    };
    void rehash(size_t capacity);

    std::vector<Entry> table_;
    size_t mask_ = 0;
    size_t size_ = 0; //!< live entries
    size_t used_ = 0; //!< live entries + tombstones
};

} // namespace zomeify
