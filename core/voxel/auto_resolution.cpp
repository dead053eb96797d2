#include "core/voxel/auto_resolution.h"

#include <algorithm>
#include <sstream>

#include "core/base/stopwatch.h"

namespace zomeify {

namespace {

std::string holes(long long genus)
{
    return genus == 1 ? "the hole through it" : "its " + std::to_string(genus) + " holes";
}

std::string explain(const AutoResolution& r, const AutoResolutionOptions& o)
{
    std::ostringstream os;
    os << r.resolution << " cells (" << r.balls << " balls): ";
    if (r.genus_kept && r.surface_genus == 0)
        os << "the coarsest grid with at least " << o.min_balls << " balls";
    else if (r.genus_kept)
        os << "the coarsest grid that keeps " << holes(r.surface_genus) << " with at least " << o.min_balls << " balls";
    else
        os << "no grid up to " << r.searched_to << " cells keeps " << holes(r.surface_genus)
           << " (parts of the shape are thinner than a strut can follow); the model will have genus " << r.genus;
    return os.str();
}

} // namespace

AutoResolution choose_resolution(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                                 const AutoResolutionOptions& options)
{
    Stopwatch clock;
    AutoResolution best;
    best.surface_genus = surface_genus;
    InitialModelOptions trial = options.initial;
    trial.b1 = 0.0;
    trial.target_genus = surface_genus;
    AutoResolution fallback; // the coarsest valid grid with enough balls, if the genus is never kept
    for (int n = std::max(2, options.min_resolution); n <= options.max_resolution; ++n)
    {
        trial.resolution = n;
        const InitialModel z0 = build_initial_model(surface, inside, trial);
        best.trials.push_back({n, z0.report.valid, z0.report.topology.genus, z0.report.seconds});
        best.searched_to = n;
        const bool enough = z0.model.nodes.size() >= options.min_balls;
        const bool kept = z0.report.valid && z0.report.topology.genus == surface_genus;
        AutoResolution& target = kept && enough ? best : fallback;
        if ((kept && enough) || (z0.report.valid && enough && fallback.resolution == 0))
        {
            target.resolution = n;
            target.balls = z0.model.nodes.size();
            target.struts = z0.model.struts.size();
            target.genus = z0.report.topology.genus;
        }
        if (kept && enough)
        {
            best.genus_kept = true;
            break;
        }
        // The time budget only cuts the search for the genus, never the search for enough balls.
        if (fallback.resolution != 0 && clock.seconds() > options.seconds)
            break;
    }
    if (!best.genus_kept)
    {
        best.resolution = fallback.resolution ? fallback.resolution : options.min_resolution;
        best.balls = fallback.balls;
        best.struts = fallback.struts;
        best.genus = fallback.genus;
    }
    best.seconds = clock.seconds();
    best.message = explain(best, options);
    return best;
}

} // namespace zomeify
