#pragma once
//! \file surface_distance.h
//! E_surface, the surface's distance to the model: points spread evenly over S (surface_samples.h),
//! each with the squared distance d² to the nearest point of the model's faces (capped at
//! surface_cap), valued d²·(1 + F(d)) and averaged. The paper's E_dist samples the model, so a
//! model can drop a thin part of S and still score well; this term gives S its say.
//!
//! Kept incrementally and exactly. Each point remembers its distance, the face it comes from (its
//! owner, with the list of points each face owns) and a lower bound of its distance to every other
//! face. A change that removes faces R and adds faces A alters only
//!   - points owned by a face of R: their nearest face is the nearest added one when that is within
//!     the lower bound (every face that stays is at least that far), and is otherwise searched
//!     among A and the faces that stay (through a grid of the model's faces);
//!   - points a face of A comes closer to than their current distance: looked for in the cells of
//!     points whose largest distance can reach A.
//! Distances are computed by one function on the faces' canonical triangles (face_triangles.h)
//! and a minimum does not depend on the order it is taken in, so the incremental sum equals, bit
//! for bit, the sum of a fresh reset().
//!
//! Threads: simulate() only reads the shared state and writes the caller's SurfaceChange, so any
//! number may run at once while no commit() or reset() does (the annealer holds its commit lock
//! shared for simulate() and exclusively for commit()). A SurfaceChange remembers the state's
//! version(): if another commit came in between, simulate again before committing.

#include <cstdint>
#include <span>
#include <vector>

#include "core/anneal/element_grid.h"
#include "core/anneal/energy/energy_options.h"
#include "core/anneal/energy/energy_samples.h"
#include "core/anneal/energy/face_shape.h"
#include "core/anneal/energy/local_change.h"
#include "core/anneal/energy/surface_samples.h"
#include "core/anneal/fixed_list.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

//! One thread's simulation of a change: the point updates a commit applies, and scratch.
class SurfaceChange
{
public:
    EnergyAccumulator delta() const noexcept { return delta_; }
    //! The SurfaceDistance::version() it was simulated against.
    uint64_t version() const noexcept { return version_; }

private:
    friend class SurfaceDistance;
    struct Update
    {
        uint32_t point;
        uint32_t owner; // a face index, an index into added_ (owner_added), or kNone
        bool owner_added;
        double d2, bound;
    };
    FixedList<FaceShape, LocalChange::kMaxFaces> added_;
    Box3 added_box_;
    FixedList<uint32_t, LocalChange::kMaxFaces> removed_faces_;
    std::vector<uint32_t> removed_mark_, updated_mark_;
    uint32_t mark_ = 0;
    std::vector<Update> updates_;
    EnergyAccumulator delta_ = 0;
    uint64_t version_ = ~uint64_t{0};
    GridVisits visits_;
};

class SurfaceDistance
{
public:
    //! Samples S (through the context's mesh and transform). Disabled (no samples, every sum 0)
    //! when options.w_surface is 0. Throws InvalidInputError for a non-positive spacing or cap.
    SurfaceDistance(const SurfaceContext& context, const EnergyOptions& options);

    bool enabled() const noexcept { return enabled_; }
    //! M, the number of points on S.
    size_t sample_count() const noexcept { return grid_.size(); }
    //! Σ of the points' values for the mesh of the last reset() and the commits since.
    EnergyAccumulator sum() const noexcept { return sum_; }
    //! Changes with every commit() and reset().
    uint64_t version() const noexcept { return version_; }

    //! Measures every point against `mesh` from scratch (also after the mesh was compacted: the
    //! owners are face indices).
    void reset(const ZomeMesh& mesh);
    //! The change of sum() that applying `change` to `mesh` would cause; `out` keeps what
    //! commit() needs.
    EnergyAccumulator simulate(const ZomeMesh& mesh, const LocalChange& change, SurfaceChange& out) const;
    //! Applies a simulated change (simulated against the current version()), after the mesh
    //! edit: `added` are the new faces' handles, in the order of change.added_faces().
    void commit(SurfaceChange& change, std::span<const Face> added);

    //! The value of one point at squared distance d2 (b0²), capped.
    EnergyFixed value(double d2) const noexcept;
    //! \name Per-point state (tests, statistics)
    //!@{
    const std::vector<Vec3>& points() const noexcept { return grid_.points(); }
    double distance_squared(size_t i) const noexcept { return d2_[i]; }
    //!@}

private:
    static constexpr uint32_t kNone = ~uint32_t{0};
    // The nearest face (best, owner) and a lower bound of every other (second).
    struct Nearest
    {
        double best, second;
        uint32_t owner;
        bool owner_added;
        //! Offers a face at distance d, which must be exact when below best; above it, any lower
        //! bound of the face's distance will do (it only enters `second`, a lower bound too).
        void offer(double d, uint32_t face, bool added) noexcept
        {
            if (d < best)
            {
                second = best;
                best = d;
                owner = face;
                owner_added = added;
            }
            else if (d < second)
                second = d;
        }
    };
    // Offers the faces of the grid that are not removed in `c` and within reach of n.best.
    void search_grid(const Vec3& p, Nearest& n, SurfaceChange& c) const;
    // Offers the added faces of `c`.
    static void search_added(const Vec3& p, Nearest& n, const SurfaceChange& c) noexcept;
    void record(uint32_t point, const Nearest& n, SurfaceChange& c) const;
    // After a commit: lowers the bound of points an added face came within reach of.
    void lower_bounds_near_added(const SurfaceChange& c);
    static void next_mark(SurfaceChange& c) noexcept;
    static bool removed(const SurfaceChange& c, uint32_t face) noexcept
    {
        return face < c.removed_mark_.size() && c.removed_mark_[face] == c.mark_;
    }
    // The list of points a face owns (intrusive, doubly linked through the points).
    void link(uint32_t point, uint32_t face);
    void unlink(uint32_t point);
    void refresh_cell_bound(uint32_t cell);

    bool enabled_ = false;
    EnergyOptions options_;
    double cap2_ = 0.0;
    SampleGrid grid_;
    ElementGrid<FaceShape> faces_;
    std::vector<double> d2_;
    std::vector<uint32_t> owner_;
    std::vector<double> bound_;         // lower bound of the squared distance to every face but the owner
    std::vector<uint32_t> first_owned_; // per face index
    std::vector<uint32_t> next_owned_, previous_owned_; // per point
    std::vector<double> cell_d2_, cell_bound_;          // per sample cell: the largest d2_ and bound_ of its points
    EnergyAccumulator sum_ = 0;
    uint64_t version_ = 0;
    SurfaceChange own_; // reset()'s scratch
    std::vector<uint32_t> touched_cells_;
};

//! E_surface's sum and point count for a whole mesh (a fresh SurfaceDistance): {0, 0} when off.
struct SurfaceSums
{
    EnergyAccumulator sum = 0;
    int64_t samples = 0;
};
SurfaceSums evaluate_surface_distance(const ZomeMesh& mesh, const SurfaceContext& context,
                                      const EnergyOptions& options);

} // namespace zomeify
