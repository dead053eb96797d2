#include "core/pipeline/kit_estimate.h"

#include <cmath>

#include "core/anneal/energy/surface_context.h"
#include "core/anneal/engine/annealer.h"
#include "core/base/stopwatch.h"

namespace zomeify {

KitEstimate estimate_kits(const SurfaceProjector& projector, const InitialModel& z0, size_t target_nodes)
{
    Stopwatch clock;
    const SurfaceContext context(projector, z0.model.transform);
    AnnealOptions quick;
    quick.threads = 1;
    quick.seed = 1;
    quick.max_proposals = kQuickPassProposals;
    quick.target_nodes = target_nodes;
    quick.repair_fold_overs = false; // the mix is what counts, not the last fold-over
    quick.progress_interval = 1e9;
    Annealer annealer(z0.model, context, quick);
    KitEstimate out;
    out.quick = parts_list(annealer.run().model);
    out.allowance = out.quick;
    out.allowance.strut_count = 0;
    for (size_t k = 0; k < kStrutKindCount; ++k)
    {
        const double growth = kAnnealedColourGrowth[k / kSizeCount];
        out.allowance.struts[k] = static_cast<size_t>(std::ceil(growth * static_cast<double>(out.quick.struts[k])));
        out.allowance.strut_count += out.allowance.struts[k];
    }
    out.plan = plan_kits(out.allowance);
    out.limits = part_limits_of(out.plan.kits);
    out.seconds = clock.seconds();
    return out;
}

PartLimits part_limits_of(const std::vector<std::pair<const Kit*, size_t>>& kits)
{
    const PartCounts have = kit_contents(kits);
    PartLimits limits;
    for (size_t k = 0; k < kStrutKindCount; ++k)
        limits.struts[k] = static_cast<uint32_t>(have[k]);
    limits.balls = static_cast<uint32_t>(have[kStrutKindCount]);
    return limits;
}

} // namespace zomeify
