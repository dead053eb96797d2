#include "core/anneal/node_claims.h"

namespace zomeify {

NodeTags::NodeTags(size_t capacity) : capacity_(capacity), owners_(new Owner[capacity]) {}

bool NodeTags::try_take(Vertex v, uint32_t owner) noexcept
{
    if (v.idx() >= capacity_)
        return false;
    uint32_t expected = 0;
    // acquire: what the previous owner committed before releasing is visible to us.
    if (owners_[v.idx()].word.compare_exchange_strong(expected, owner, std::memory_order_acquire,
                                                      std::memory_order_relaxed))
        return true;
    return expected == owner;
}

void NodeTags::release(Vertex v, uint32_t owner) noexcept
{
    if (v.idx() >= capacity_)
        return;
    // Only the owner releases, so a plain store does (no locked instruction on x86).
    // release: our commit's writes are published to the next owner.
    if (owners_[v.idx()].word.load(std::memory_order_relaxed) == owner)
        owners_[v.idx()].word.store(0, std::memory_order_release);
}

uint32_t NodeTags::owner(Vertex v) const noexcept
{
    return v.idx() < capacity_ ? owners_[v.idx()].word.load(std::memory_order_acquire) : 0;
}

bool Claims::take(Vertex v) noexcept
{
    if (holds(v))
        return true;
    if (held_.size() == held_.capacity())
        return false;
    if (tags_ && !tags_->try_take(v, owner_))
        return false;
    held_.push_back(v);
    return true;
}

bool Claims::holds(Vertex v) const noexcept
{
    for (const Vertex& h : held_)
        if (h == v)
            return true;
    return false;
}

void Claims::release_all() noexcept
{
    if (tags_)
        for (const Vertex& v : held_)
            tags_->release(v, owner_);
    held_.clear();
}

} // namespace zomeify
