#include "core/geom/projection_cache.h"

#include "core/base/hash.h"

#include <algorithm>
#include <bit>
#include <mutex>

#include "core/base/spin_lock.h"
#include <utility>
#include <vector>

namespace zomeify {
namespace {

// The caller's key may be a weak hash of small integers; mix it so both the shard (high bits)
// and the slot (low bits) see every input bit.
uint64_t mix(uint64_t x) { return mix64(x); }

struct Entry
{
    uint64_t key = 0;
    Vec3 point = Vec3::Zero();
    ClosestPoint value;
    bool used = false;
};

// Open addressing with linear probing at load factor at most 1/2; entries are never removed one
// by one, only all at once, so no tombstones are needed.
class Table
{
public:
    void init(size_t limit)
    {
        limit_ = limit;
        slots_.assign(std::bit_ceil(2 * limit), Entry{});
        mask_ = slots_.size() - 1;
    }
    bool full() const { return size_ >= limit_; }
    size_t size() const { return size_; }
    void clear()
    {
        if (size_ > 0)
        {
            std::fill(slots_.begin(), slots_.end(), Entry{});
            size_ = 0;
        }
    }
    const Entry* find(uint64_t hash, uint64_t key) const
    {
        for (size_t i = hash & mask_;; i = (i + 1) & mask_)
        {
            const Entry& e = slots_[i];
            if (!e.used)
            {
                return nullptr;
            }
            if (e.key == key)
            {
                return &e;
            }
        }
    }
    // Caller makes sure the table is not full.
    void put(uint64_t hash, uint64_t key, const Vec3& p, const ClosestPoint& value)
    {
        for (size_t i = hash & mask_;; i = (i + 1) & mask_)
        {
            Entry& e = slots_[i];
            if (!e.used || e.key == key)
            {
                size_ += e.used ? 0 : 1;
                e = Entry{key, p, value, true};
                return;
            }
        }
    }

private:
    std::vector<Entry> slots_;
    size_t mask_ = 0;
    size_t size_ = 0;
    size_t limit_ = 1;
};

} // namespace

struct alignas(64) ProjectionCache::Shard
{
    SpinLock mutex; // held for one probe: see spin_lock.h
    Table current;
    Table previous;
    uint64_t rotations = 0;
    uint64_t hits = 0, misses = 0; // project()'s lookups

    // Called with the lock held.
    void put(uint64_t hash, uint64_t key, const Vec3& p, const ClosestPoint& value)
    {
        if (current.full() && current.find(hash, key) == nullptr)
        {
            std::swap(current, previous);
            current.clear();
            ++rotations;
        }
        current.put(hash, key, p, value);
    }
};

ProjectionCache::ProjectionCache(const SurfaceProjector& projector, const ProjectionCacheOptions& options)
    : projector_(projector)
{
    const size_t capacity = std::max<size_t>(options.capacity, 2);
    shard_count_ = std::bit_floor(std::clamp<size_t>(options.shards, 1, capacity / 2));
    // Two generations per shard, each of at most `limit` entries: at most `capacity` in all.
    const size_t limit = std::max<size_t>(1, capacity / (2 * shard_count_));
    shards_ = std::make_unique<Shard[]>(shard_count_);
    for (size_t s = 0; s < shard_count_; ++s)
    {
        shards_[s].current.init(limit);
        shards_[s].previous.init(limit);
    }
}

ProjectionCache::~ProjectionCache() = default;

ProjectionCache::Shard& ProjectionCache::shard_of(uint64_t hash) const
{
    return shards_[(hash >> 40) & (shard_count_ - 1)];
}

std::optional<ClosestPoint> ProjectionCache::find(uint64_t key, const Vec3& p) { return lookup(key, p, false); }

// Counted in the shard, under the lock already held: a counter shared by all threads would be
// written by every lookup of every thread, and that one cache line would bounce between cores.
std::optional<ClosestPoint> ProjectionCache::lookup(uint64_t key, const Vec3& p, bool count)
{
    const uint64_t hash = mix(key);
    Shard& shard = shard_of(hash);
    std::lock_guard lock(shard.mutex);
    if (const Entry* e = shard.current.find(hash, key); e != nullptr && e->point == p)
    {
        shard.hits += count ? 1 : 0;
        return e->value;
    }
    if (const Entry* e = shard.previous.find(hash, key); e != nullptr && e->point == p)
    {
        // Copy before put(): a rotation clears the table `e` points into.
        const ClosestPoint value = e->value;
        shard.put(hash, key, p, value);
        shard.hits += count ? 1 : 0;
        return value;
    }
    shard.misses += count ? 1 : 0;
    return std::nullopt;
}

void ProjectionCache::insert(uint64_t key, const Vec3& p, const ClosestPoint& value)
{
    const uint64_t hash = mix(key);
    Shard& shard = shard_of(hash);
    std::lock_guard lock(shard.mutex);
    shard.put(hash, key, p, value);
}

ClosestPoint ProjectionCache::project(uint64_t key, const Vec3& p, uint32_t hint)
{
    if (std::optional<ClosestPoint> cached = lookup(key, p, true))
        return *cached;
    // Computed without holding the shard lock: two threads missing on the same point may both
    // compute it, which is cheaper than making every other thread of the shard wait.
    const ClosestPoint value = hint == kNoHint ? projector_.project(p) : projector_.project(p, hint);
    insert(key, p, value);
    return value;
}

void ProjectionCache::clear()
{
    for (size_t s = 0; s < shard_count_; ++s)
    {
        std::lock_guard lock(shards_[s].mutex);
        shards_[s].current.clear();
        shards_[s].previous.clear();
        shards_[s].rotations = shards_[s].hits = shards_[s].misses = 0;
    }
}

ProjectionCacheStats ProjectionCache::stats() const
{
    ProjectionCacheStats out;
    for (size_t s = 0; s < shard_count_; ++s)
    {
        std::lock_guard lock(shards_[s].mutex);
        out.rotations += shards_[s].rotations;
        out.hits += shards_[s].hits;
        out.misses += shards_[s].misses;
        out.size += shards_[s].current.size() + shards_[s].previous.size();
    }
    return out;
}

} // namespace zomeify
