#pragma once
//! \file projection_cache.h
//! A cache of π(p) for exact lattice positions, shared by the annealing threads (design §3.7).
//! Nodes, strut midpoints and face barycentres come back to the same exact positions again and
//! again; the caller hashes the exact integer coordinates into a 64-bit key.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>

#include "core/geom/closest_point.h"

namespace zomeify {

struct ProjectionCacheOptions
{
    //! Most entries held at once (memory is about 256 bytes per entry of capacity).
    size_t capacity = size_t{1} << 16;
    //! Independent locks; rounded down to a power of two, at most capacity / 2.
    size_t shards = 64;
};

//! Counters since construction (or the last clear()).
struct ProjectionCacheStats
{
    uint64_t hits = 0;
    uint64_t misses = 0;
    uint64_t rotations = 0; //!< generation changes, each dropping the oldest generation of one shard
    size_t size = 0;        //!< entries held now (an entry may be held in both generations)
};

//! Thread-safe map from (key, p) to π(p). Entries are split by the key's hash into shards, each
//! guarded by its own mutex and holding two generations of an open-addressing table.
//!
//! Policy (bounded, no per-hit bookkeeping): inserts go to the current generation; when it is
//! full, the previous generation is dropped and the current one becomes previous. A hit in the
//! previous generation is copied back into the current one. So an entry survives as long as it
//! is used at least once per capacity/2 insertions into its shard, and the cache never holds more
//! than `capacity` entries. Dropping entries is always safe: values are a pure function of p.
//!
//! The stored point is compared exactly on lookup, so a 64-bit key collision between two
//! positions costs a recomputation, never a wrong answer; one key holds one point at a time.
class ProjectionCache
{
public:
    //! Keeps a reference to `projector`, which must outlive the cache.
    explicit ProjectionCache(const SurfaceProjector& projector, const ProjectionCacheOptions& options = {});
    ~ProjectionCache();
    ProjectionCache(const ProjectionCache&) = delete;
    ProjectionCache& operator=(const ProjectionCache&) = delete;

    static constexpr uint32_t kNoHint = ~uint32_t{0};
    //! π(p) from the cache, computed by the projector (outside any lock) and stored on a miss;
    //! `hint` (a triangle near π(p), e.g. a neighbour's) speeds up that search, never its answer.
    ClosestPoint project(uint64_t key, const Vec3& p, uint32_t hint = kNoHint);
    //! The cached value for (key, p), if any.
    std::optional<ClosestPoint> find(uint64_t key, const Vec3& p);
    //! Stores `value` for (key, p), replacing what `key` held.
    void insert(uint64_t key, const Vec3& p, const ClosestPoint& value);
    //! Drops every entry and resets the counters.
    void clear();

    ProjectionCacheStats stats() const;
    const SurfaceProjector& projector() const { return projector_; }

private:
    struct Shard;

    Shard& shard_of(uint64_t hash) const;
    std::optional<ClosestPoint> lookup(uint64_t key, const Vec3& p, bool count);

    const SurfaceProjector& projector_;
    std::unique_ptr<Shard[]> shards_;
    size_t shard_count_ = 1;
};

} // namespace zomeify
