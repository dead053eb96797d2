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
//! Distances are
//! computed by one function on the faces' canonical triangles (face_triangles.h) and a minimum
//! does not depend on the order it is taken in, so the incremental sum equals, bit for bit, the
//! sum of a fresh reset().
//!
//! Not thread-safe: simulate() reads, and commit() writes, the per-point state and the face grid
//! (the annealer calls both inside its commit section).

#include <cstdint>
#include <span>
#include <vector>

#include "core/anneal/energy_options.h"
#include "core/anneal/energy_samples.h"
#include "core/anneal/element_grid.h"
#include "core/anneal/face_shape.h"
#include "core/anneal/fixed_list.h"
#include "core/anneal/local_change.h"
#include "core/anneal/surface_samples.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

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

    //! Measures every point against `mesh` from scratch (also after the mesh was compacted: the
    //! owners are face indices).
    void reset(const ZomeMesh& mesh);
    //! The change of sum() that applying `change` to `mesh` would cause. Remembers what commit()
    //! needs; valid until the next simulate() or reset().
    EnergyAccumulator simulate(const ZomeMesh& mesh, const LocalChange& change);
    //! Applies the last simulated change, after the mesh edit: `added` are the new faces' handles,
    //! in the order of change.added_faces().
    void commit(std::span<const Face> added);

    //! The value of one point at squared distance d2 (b0²), capped.
    EnergyFixed value(double d2) const noexcept;
    //! \name Per-point state (tests, statistics)
    //!@{
    const std::vector<Vec3>& points() const noexcept { return grid_.points(); }
    double distance_squared(size_t i) const noexcept { return d2_[i]; }
    //!@}

private:
    static constexpr uint32_t kNone = ~uint32_t{0};
    struct Update
    {
        uint32_t point;
        uint32_t owner; // a face index, an index into added_ (owner_added), or kNone
        bool owner_added;
        double d2, bound;
    };
    // The nearest face (best, owner) and a lower bound of every other (second).
    struct Nearest
    {
        double best, second;
        uint32_t owner;
        bool owner_added;
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
    // Offers the faces of the grid that are not removed and within reach of n.best.
    void search_grid(const Vec3& p, Nearest& n) const;
    // Offers the added faces.
    void search_added(const Vec3& p, Nearest& n) const noexcept;
    void record(uint32_t point, const Nearest& n);
    // After a commit: lowers the bound of points an added face came within reach of.
    void lower_bounds_near_added();
    void next_mark() noexcept;
    bool removed(uint32_t face) const noexcept { return face < removed_mark_.size() && removed_mark_[face] == mark_; }
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
    std::vector<double> bound_; // lower bound of the squared distance to every face but the owner
    std::vector<uint32_t> first_owned_; // per face index
    std::vector<uint32_t> next_owned_, previous_owned_; // per point
    std::vector<double> cell_d2_, cell_bound_; // per sample cell: the largest d2_ and bound_ of its points
    EnergyAccumulator sum_ = 0;

    // The last simulated change.
    FixedList<FaceShape, LocalChange::kMaxFaces> added_;
    Box3 added_box_;
    FixedList<uint32_t, LocalChange::kMaxFaces> removed_faces_;
    std::vector<uint32_t> removed_mark_, updated_mark_;
    uint32_t mark_ = 0;
    std::vector<Update> updates_;
    std::vector<uint32_t> touched_cells_;
    EnergyAccumulator delta_ = 0;
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
