#pragma once
//! \file fold_repair.h
//! After the cooling schedule: removes the fold-overs the annealing left. No commit may add one,
//! but Z0 has some (a voxel face across a thin part faces the wrong side of S), and a short run
//! may end before the seeds reach them. A greedy descent on proposals seeded at the corners of
//! the fold-over faces: a proposal that removes a fold-over and lowers E (whose fold-over term
//! pays w_fold for each one removed) is applied if it passes every commit check. Deterministic
//! (its own random stream of the run's seed).

#include <cstddef>
#include <cstdint>

namespace zomeify {

struct AnnealerState;

struct FoldRepairStats
{
    int64_t before = 0, after = 0; //!< fold-over faces
    uint64_t proposals = 0, commits = 0;
};

//! Runs alone (the workers have ended); takes the commit lock, since progress() and snapshot()
//! may still be called from other threads.
FoldRepairStats repair_fold_overs(AnnealerState& state);

} // namespace zomeify
