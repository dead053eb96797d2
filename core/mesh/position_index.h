#pragma once
//! \file position_index.h
//! PositionIndex: the exact position → node map behind "no two nodes at one position". Open
//! addressing with linear probing in a power-of-two table at most half full, so a lookup is one
//! hash and, typically, one or two cache lines; erased entries leave tombstones, cleared by the
//! next rehash. Lookups are const and safe from many threads as long as nobody inserts or erases
//! meanwhile; reserve() ahead makes inserts rehash-free up to that many entries.

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
        if (size_ == 0)
            return {};
        for (size_t i = ZVecHash()(p) & mask_;; i = (i + 1) & mask_)
        {
            const Entry& e = table_[i];
            if (e.value == kEmpty)
                return {};
            if (e.value != kTombstone && e.key == p)
                return Vertex(e.value);
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
            if (e.value != kEmpty && e.value != kTombstone)
                f(e.key, Vertex(e.value));
    }

private:
    static constexpr MeshIndex kEmpty = kInvalidMeshIndex;
    static constexpr MeshIndex kTombstone = kInvalidMeshIndex - 1;
    struct Entry
    {
        ZVec key;
        MeshIndex value = kEmpty;
    };
    void rehash(size_t capacity);

    std::vector<Entry> table_;
    size_t mask_ = 0;
    size_t size_ = 0; //!< live entries
    size_t used_ = 0; //!< live entries + tombstones
};

} // namespace zomeify
