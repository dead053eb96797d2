#pragma once
//! \file anneal_stats.h
//! What an annealing run reports while it works (AnnealProgress) and when it ends (AnnealStats).

#include <array>
#include <cstdint>

#include "core/anneal/energy/energy_sums.h"
#include "core/anneal/proposal.h"

namespace zomeify {

//! A consistent view of a running annealer (taken under the commit lock, so the energy, the
//! counts and the model all belong to one state).
struct AnnealProgress
{
    double elapsed_seconds = 0.0;
    double fraction = 0.0;    //!< of the budget (time or proposals) used, in [0, 1]
    double temperature = 0.0; //!< current T
    EnergyTerms energy;       //!< E and its terms now (energy.sums.nodes = N)
    double best_energy = 0.0; //!< lowest E at a progress sample so far
    size_t nodes = 0, struts = 0, faces = 0;
    uint64_t proposals = 0;       //!< propose() calls
    uint64_t valid_proposals = 0; //!< proposals that were valid (reached the Metropolis test)
    uint64_t commits = 0;         //!< accepted and applied
    double acceptance_rate = 0.0; //!< commits / valid proposals
    bool finished = false;
};

//! Counters per operator kind.
struct OperatorCounts
{
    uint64_t proposed = 0; //!< propose() calls of this kind
    uint64_t valid = 0;    //!< valid proposals
    uint64_t accepted = 0; //!< committed
};

struct AnnealStats
{
    double wall_seconds = 0.0;
    int threads = 1;
    uint64_t proposals = 0, valid_proposals = 0, commits = 0;
    double proposals_per_second = 0.0, commits_per_second = 0.0;
    double initial_temperature = 0.0, min_temperature = 0.0;
    int t0_valid_samples = 0; //!< valid proposals T0 was estimated from
    bool cancelled = false;
    std::array<OperatorCounts, kOperatorKinds> per_operator{};
    std::array<uint64_t, kRejectionKinds> rejections{}; //!< why proposals were not valid
    uint64_t busy_seeds = 0;                            //!< seed draws that found the node claimed by another thread
    uint64_t dead_seeds = 0;                            //!< seed draws that hit a deleted node slot
    uint64_t lost_races = 0; //!< accepted proposals dropped at commit (position taken meanwhile)
    //! Accepted proposals decided again at commit (E_surface, Metropolis, clearance) because
    //! another thread committed in between.
    uint64_t redecisions = 0;
    uint64_t garbage_collections = 0; //!< synchronized pauses to compact and grow the mesh
    //! Seconds the threads spent in the commit section (holding the commit lock exclusively, so no
    //! other thread could decide or commit meanwhile) and waiting to enter it, summed over threads:
    //! the serial part of a run (engine README, "Many cores").
    double commit_hold_seconds = 0.0, commit_wait_seconds = 0.0;
    //! The coverage guard (coverage_guard.h): its radius (0: off), samples on S, and how many of
    //! them had no node within the radius at the start and at the end.
    double coverage_radius = 0.0;
    size_t coverage_samples = 0, uncovered_at_start = 0, uncovered_at_end = 0;
    //! Fold-over faces when the schedule ended and after the repair (fold_repair.h), and the
    //! repair's proposals and commits.
    int64_t fold_overs_before_repair = 0, fold_overs_after_repair = 0;
    uint64_t repair_proposals = 0, repair_commits = 0;
    //! After the run the incremental sums equalled a fresh evaluation, bit for bit.
    bool energy_consistent = false;
};

} // namespace zomeify
