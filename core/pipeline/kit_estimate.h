#pragma once
//! \file kit_estimate.h
//! The kits named before a run, and the limits that make them hold (issue 38). A short annealing
//! pass from Z0 (kQuickPassProposals, one thread, seed 1: the same answer natively and in wasm)
//! gives this shape's strut mix at the run's ball target; a default run then moves part of its
//! longer struts to the shortest length of each colour, so the mix is raised per colour (blue
//! ×1.1, yellow ×1.2, red ×1.4, chosen on the ten shared meshes: docs/page.md) and the kits that
//! hold it are named. A run given `limits` keeps within those kits (part_tally.h), so a buyer of
//! the named kits can build the model it makes.

#include "core/anneal/engine/anneal_options.h"
#include "core/geom/closest_point.h"
#include "core/parts/kits.h"
#include "core/parts/parts_list.h"
#include "core/voxel/initial_model.h"

namespace zomeify {

inline constexpr uint64_t kQuickPassProposals = 300000;

struct KitEstimate
{
    PartsList quick;     //!< the parts after the quick pass ("typically")
    PartsList allowance; //!< raised per colour: what the named kits must hold
    KitPlan plan;        //!< the kits named ("at most")
    PartLimits limits;   //!< the named kits' contents: the run's part limits
    double seconds = 0.0;
};

//! The parts each colour is raised by (blue, yellow, red).
inline constexpr std::array<double, 3> kAnnealedColourGrowth = {1.1, 1.2, 1.4};

//! Kits for a run from `z0` towards `target_nodes` balls (0: Z0's count) against the surface.
KitEstimate estimate_kits(const SurfaceProjector& projector, const InitialModel& z0, size_t target_nodes);

//! The contents of `kits` as part limits.
PartLimits part_limits_of(const std::vector<std::pair<const Kit*, size_t>>& kits);

} // namespace zomeify
