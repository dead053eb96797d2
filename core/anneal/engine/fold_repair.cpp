#include "core/anneal/engine/fold_repair.h"

#include <algorithm>
#include <mutex>
#include <vector>

#include "core/anneal/energy/element_energy.h"
#include "core/anneal/engine/annealer_state.h"
#include "core/anneal/engine/schedule.h"
#include "core/anneal/proposal.h"
#include "core/mesh/circulators.h"
#include "core/mesh/element_ranges.h"

namespace zomeify {
namespace {

// Rounds of local annealing around the fold-overs left, proposals per seed node in a round, and the
// temperature of the first round as a fraction of the schedule's start (the last round is cold).
// 40 rounds from 0.2·T0 left 0 fold-overs where 12 rounds from 0.05·T0 left 1-2 (bunny and
// fertility at 16 cells, fertility at 15, scorpion at 12, 2·10^4 proposals; engine README).
constexpr int kRounds = 40;
constexpr int kProposalsPerSeed = 40;
constexpr double kFirstTemperature = 0.2;
// The repair's own random stream (apart from the workers' and T0's).
constexpr uint64_t kStream = 0xF01D;

// The nodes within two struts of a fold-over face: a single move there rarely removes one (every
// face that could replace it lies across the same thin part), but moves around it can make room.
std::vector<Vertex> seeds_near_fold_overs(const AnnealerState& s)
{
    std::vector<Vertex> near;
    NodeNormals normals(s.context);
    for (Face f : faces(s.mesh))
    {
        normals.clear();
        if (!face_energy(s.mesh, f, normals, s.options.energy).fold_over)
            continue;
        for (Vertex v : face_vertices(s.mesh, f))
            for (Vertex w : adjacent_vertices(s.mesh, v))
            {
                near.push_back(w);
                for (Vertex x : adjacent_vertices(s.mesh, w))
                    near.push_back(x);
            }
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    return near;
}

} // namespace

FoldRepairStats repair_fold_overs(AnnealerState& s)
{
    std::lock_guard lock(s.commit_lock);
    FoldRepairStats stats;
    stats.before = stats.after = s.energy.sums().fold_overs;
    if (stats.before <= 0)
        return stats;
    // Room for every repair commit, so no compaction renumbers the seeds on the way.
    s.make_room();
    Rng rng = Rng::for_stream(s.options.seed, kStream);
    Claims claims; // unshared: every claim succeeds
    Proposal proposal;
    SurfaceChange surface;
    for (int round = 0; round < kRounds && s.energy.sums().fold_overs > 0; ++round)
    {
        // Cooling from a warm start to zero, so the last rounds keep only what lowers E.
        const double fraction = 1.0 - static_cast<double>(round + 1) / kRounds;
        const double temperature = kFirstTemperature * s.schedule.initial() * fraction;
        const std::vector<Vertex> seeds = seeds_near_fold_overs(s);
        for (int i = 0; i < kProposalsPerSeed * static_cast<int>(seeds.size()); ++i)
        {
            const Vertex seed = seeds[rng.below(seeds.size())];
            const auto kind = static_cast<OperatorKind>(rng.below(kOperatorKinds));
            const double u = rng.uniform01();
            if (s.mesh.is_deleted(seed))
                continue;
            claims.take(seed);
            ++stats.proposals;
            if (propose(kind, s.mesh, seed, rng, claims, proposal))
            {
                EnergyDelta delta = s.energy.simulate(s.mesh, proposal.change);
                // A move may trade a fold-over for another one nearby (walking it to where it can
                // go) but never raise their number.
                if (delta.ok() && delta.sums.fold_overs <= 0)
                {
                    s.energy.add_surface_change(s.mesh, proposal.change, delta, surface);
                    const double de = s.energy.delta_energy(delta);
                    const bool accept = temperature > 0.0 ? metropolis_accept(de, temperature, u) : de < 0.0;
                    if (accept && s.apply_accepted(proposal, delta, surface) == Rejection::None)
                        ++stats.commits;
                }
            }
            claims.release_all();
        }
    }
    stats.after = s.energy.sums().fold_overs;
    return stats;
}

} // namespace zomeify
