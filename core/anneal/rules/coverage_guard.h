#pragma once
//! \file coverage_guard.h
//! Keeps the model from giving up a part of the surface. The energy (paper §4) measures how far
//! the model is from S, never how far S is from the model, so a model can lower E by pulling away
//! from a thin part: the bunny's ear tips were left uncovered in a third of the runs with a cold
//! start (engine README, "Cooling"). The guard holds sample points spread evenly over S and, for
//! each, the number of model nodes within `radius`; a commit that would take some sample's count
//! from one or more to zero is refused. Samples out of every node's reach in the starting model
//! are held to it only once a node comes within reach.
//!
//! Counts depend on node positions only (not on node numbers), so compaction leaves them valid.
//! Not thread-safe: the annealer calls it inside the commit section.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/anneal/energy/local_change.h"
#include "core/anneal/energy/surface_context.h"
#include "core/mesh/zome_mesh.h"

namespace zomeify {

struct CoverageOptions
{
    //! A sample counts as covered by the nodes within this distance (b0 units); 0 turns the guard off.
    double radius = 2.5;
    //! Spacing of the samples on S (b0 units).
    double spacing = 0.5;
};

class CoverageGuard
{
public:
    //! Samples S (through ctx's projector mesh and transform) and counts the nodes of `start`.
    //! Throws InvalidInputError for a negative or non-finite radius or a non-positive spacing.
    CoverageGuard(const SurfaceContext& ctx, const ZomeMesh& start, const CoverageOptions& options);

    bool enabled() const noexcept { return radius_ > 0.0; }
    //! Whether applying `change` to `mesh` leaves every covered sample covered. If so, the counts
    //! are updated as if it were applied (call it right before apply_proposal, and apply it).
    bool admit(const ZomeMesh& mesh, const LocalChange& change);

    size_t sample_count() const noexcept { return samples_.size(); }
    //! Samples with no node within the radius now.
    size_t uncovered() const noexcept;
    //! The count of sample i (tests).
    uint32_t count(size_t i) const { return counts_[i]; }
    //! Recounts from scratch (tests: must equal the incremental counts).
    std::vector<uint32_t> recount(const ZomeMesh& mesh) const;

private:
    struct Cell
    {
        uint32_t begin, end; // range in samples_
    };
    //! Calls f(sample index) for every sample within the radius of p (Zome units).
    template <typename F>
    void for_samples_near(const Vec3& p, F&& f) const;
    void add_pending(const Vec3& p, int delta);

    double radius_ = 0.0;
    double radius_squared_ = 0.0;
    std::vector<Vec3> samples_;                // sorted by cell
    std::unordered_map<uint64_t, Cell> cells_; // packed cell coordinates → samples
    std::vector<uint32_t> counts_;
    std::vector<int32_t> pending_; // net change of a commit under test, zero between calls
    std::vector<uint32_t> touched_;
};

} // namespace zomeify
