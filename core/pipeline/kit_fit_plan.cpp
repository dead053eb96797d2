#include "core/pipeline/kit_fit_plan.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "core/parts/kit_fit.h"
#include "core/parts/parts_list.h"
#include "core/pipeline/pipeline.h"
#include "core/voxel/initial_model.h"

namespace zomeify {

namespace {

struct Probe
{
    int resolution;
    size_t nodes;
    bool kept;
    double size_cm;
};

std::string cm_text(double cm)
{
    std::ostringstream s;
    s << std::lround(cm) << " cm";
    return s.str();
}

} // namespace

KitFitPlan plan_kit_fit(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                        const SurfaceProbeAt& probe, size_t ball_budget, int max_resolution)
{
    KitFitPlan plan;
    plan.ball_budget = ball_budget;
    max_resolution = std::clamp(max_resolution, kMinResolution, kMaxResolution);
    std::optional<Probe> best_kept, best_any, smallest;
    // Z0's ball count grows about with the square of the resolution: once it is well past the
    // budget no finer grid comes back under it, so the search ends there (a few Z0s in all).
    for (int r = 3; r <= max_resolution; ++r)
    {
        InitialModelOptions o;
        o.resolution = r;
        o.target_genus = surface_genus;
        o.surface_probe = probe;
        const InitialModel z0 = build_initial_model(surface, inside, o);
        if (!z0.report.valid)
            continue;
        const PartsList parts = parts_list(z0.model);
        const Probe p{r, z0.model.nodes.size(), z0.report.topology.genus == surface_genus,
                      *std::max_element(parts.size_cm.begin(), parts.size_cm.end())};
        if (!smallest)
            smallest = p;
        // The annealer pulls the ball count toward the target, so a Z0 a little over the budget
        // still ends near it (the result is checked either way).
        if (p.nodes <= ball_budget + ball_budget / 5)
        {
            best_any = p;
            if (p.kept)
                best_kept = p;
        }
        else if (p.nodes > ball_budget * 3 / 2)
            break;
    }
    const std::optional<Probe> chosen = best_kept ? best_kept : best_any;
    std::ostringstream msg;
    if (!chosen)
    {
        msg << "no size of this shape fits: the smallest model (" << (smallest ? smallest->resolution : 3)
            << " cells, about " << (smallest ? cm_text(smallest->size_cm) : std::string("?")) << ") needs about "
            << (smallest ? smallest->nodes : 0) << " balls and your kits allow about " << ball_budget;
        plan.message = msg.str();
        return plan;
    }
    plan.possible = true;
    plan.resolution = chosen->resolution;
    plan.z0_nodes = chosen->nodes;
    plan.genus_kept = chosen->kept;
    plan.size_cm = chosen->size_cm;
    // Z0's own count, as a run without a target takes, unless that is over the budget: a grid much
    // coarser than the budget (a size asked) is not filled up with extra balls.
    plan.target_nodes = std::max<size_t>(4, std::min(ball_budget, plan.z0_nodes));
    msg << "fit to your kits: " << plan.resolution << " cells (about " << cm_text(plan.size_cm) << "), target "
        << plan.target_nodes << " balls";
    if (!plan.genus_kept)
        msg << "; no size within your kits keeps the shape's holes";
    plan.message = msg.str();
    return plan;
}

} // namespace zomeify
