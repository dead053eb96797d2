#pragma once
//! \file surface_context.h
//! SurfaceContext: what the energy needs to know about the input surface S for one sample of the
//! Zome mesh (design.md §3.3, §3.7): the squared distance to π(p) in b0 units, the side of S the
//! sample is on (which forbidden zone applies) and the surface normal at π(p).
//!
//! Samples are given exactly, as a LatticeSum and a divisor (node: 1, strut midpoint: 2, face
//! barycentre: 3 or 4), mapped to mesh units by the model transform and looked up in two caches
//! keyed by the exact sum: first a small direct-mapped cache of finished samples private to the
//! calling thread (no lock, no shared write: annealing threads do not slow each other down), then
//! the ProjectionCache shared by all threads, then the projector. A position that comes back (the
//! common case in annealing) costs one probe of the thread's own table.

#include <atomic>

#include "core/anneal/energy/lattice_sum.h"
#include "core/geom/closest_point.h"
#include "core/geom/inside.h"
#include "core/geom/projection_cache.h"
#include "core/zome/model.h"

namespace zomeify {

//! The surface quantities of one sample.
struct SurfaceSample
{
    double distance_squared = 0.0; //!< ‖p − π(p)‖² in b0² (mesh distance / transform scale, squared)
    Vec3 normal = Vec3::UnitZ();   //!< unit outward normal of S at π(p) (SurfaceProjector's)
    bool inside = false;           //!< p strictly inside S (InsideTest; points on S are outside)
    uint32_t triangle = 0;         //!< the triangle of S that holds π(p)
};

//! Immutable after construction except for its cache, which is thread-safe: sample() may be called
//! from any number of threads at once. Holds a reference to the projector, which must outlive it.
class SurfaceContext
{
public:
    //! Throws InvalidInputError if the transform's scale is not a positive finite number.
    SurfaceContext(const SurfaceProjector& projector, const ModelTransform& transform,
                   const ProjectionCacheOptions& cache = {});
    SurfaceContext(const SurfaceContext&) = delete;
    SurfaceContext& operator=(const SurfaceContext&) = delete;

    //! The sample at sum / divisor (Zome units). `near`: a node close to the sample (a corner of its
    //! strut or face), whose projection then seeds the search when the sample is in no cache; the
    //! value never depends on it.
    SurfaceSample sample(const LatticeSum& sum, int divisor, const ZVec* near = nullptr) const noexcept;
    //! The sample at a node position.
    SurfaceSample node_sample(const ZVec& p) const noexcept { return sample(lattice_sum(p), 1); }
    //! Only the surface normal at π(p) of a node position (no inside test).
    Vec3 node_normal(const ZVec& p) const noexcept;

    //! Zome units → mesh units (p_mesh = scale · p + translation).
    Vec3 to_mesh(const Vec3& zome) const noexcept { return scale_ * zome + translation_; }

    const ModelTransform& transform() const noexcept { return transform_; }
    const SurfaceProjector& projector() const noexcept { return projector_; }
    //! Cache counters (hits, misses, size).
    ProjectionCacheStats cache_stats() const { return cache_.stats(); }
    //! Empties the caches, every thread's included (results never change; only speed does). Not
    //! while another thread samples.
    void clear_cache();

private:
    const SurfaceProjector& projector_;
    InsideTest inside_;
    ModelTransform transform_;
    double scale_ = 1.0;
    Vec3 translation_ = Vec3::Zero();
    double inv_scale_squared_ = 1.0;
    //! Mutable because a lookup stores what it computed; values are a pure function of the point.
    mutable ProjectionCache cache_;
    //! Names this context (and this content of its caches) for the threads' private caches, which
    //! start over when the context they served is not this one any more.
    std::atomic<uint64_t> generation_;
};

} // namespace zomeify
