#include "core/mesh/position_index.h"

#include <utility>

namespace zomeify {

bool PositionIndex::insert(const ZVec& p, Vertex v)
{
    if (!has_capacity_for(1))
        rehash(table_.empty() ? 16 : (2 * (size_ + 1) > table_.size() / 2 ? 2 * table_.size() : table_.size()));
    size_t tomb = table_.size();
    for (size_t i = ZVecHash()(p) & mask_;; i = (i + 1) & mask_)
    {
        Entry& e = table_[i];
        if (e.value == kEmpty)
        {
            // Reuse the first tombstone on the probe path: keeps chains short under churn.
            Entry& target = tomb < table_.size() ? table_[tomb] : e;
            if (&target == &e)
                ++used_;
            target.key = p;
            target.value = v.idx();
            ++size_;
            return true;
        }
        if (e.value == kTombstone)
        {
            if (tomb == table_.size())
                tomb = i;
        }
        else if (e.key == p)
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
        if (e.value == kEmpty)
            return false;
        if (e.value != kTombstone && e.key == p)
        {
            e.value = kTombstone;
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
        if (e.value != kEmpty && e.value != kTombstone)
            insert(e.key, Vertex(e.value));
}

} // namespace zomeify
