#include "core/mesh/position_index.h"

#include <utility>

namespace zomeify {

bool PositionIndex::insert(const ZVec& p, Vertex v)
{
    if (!has_capacity_for(1))
        rehash(table_.empty() ? 16 : (4 * (size_ + 1) > table_.size() ? 2 * table_.size() : table_.size()));
    for (size_t i = ZVecHash()(p) & mask_;; i = (i + 1) & mask_)
    {
        Entry& e = table_[i];
        const MeshIndex value = e.value.load(std::memory_order_relaxed);
        if (value == kEmpty)
        {
            e.key = p;
            e.value.store(v.idx(), std::memory_order_release);
            ++size_;
            ++used_;
            return true;
        }
        if (value != kTombstone && e.key == p)
            return false;
    }
}

bool PositionIndex::erase(const ZVec& p)
{
    if (size_ == 0)
        return false;
    for (size_t i = ZVecHash()(p) & mask_;; i = (i + 1) & mask_)
    {
        Entry& e = table_[i];
        const MeshIndex value = e.value.load(std::memory_order_relaxed);
        if (value == kEmpty)
            return false;
        if (value != kTombstone && e.key == p)
        {
            e.value.store(kTombstone, std::memory_order_release);
            --size_;
            return true;
        }
    }
}

void PositionIndex::reserve(size_t n)
{
    if (!has_capacity_for(n > size_ ? n - size_ : 0))
    {
        size_t capacity = 16;
        while (capacity < 2 * n)
            capacity *= 2;
        rehash(capacity);
    }
}

void PositionIndex::clear()
{
    table_.clear();
    mask_ = 0;
    size_ = used_ = 0;
}

void PositionIndex::rehash(size_t capacity)
{
    // A rehash drops the tombstones, so under steady churn it can keep the same capacity.
    while (capacity < 2 * (size_ + 1))
        capacity *= 2;
    std::vector<Entry> old = std::move(table_);
    table_.assign(capacity, Entry{});
    mask_ = capacity - 1;
    size_ = used_ = 0;
    for (const Entry& e : old)
    {
        const MeshIndex value = e.value.load(std::memory_order_relaxed);
        if (value != kEmpty && value != kTombstone)
            insert(e.key, Vertex(value));
    }
}

} // namespace zomeify
