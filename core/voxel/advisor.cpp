#include "core/voxel/advisor.h"

#include <algorithm>
#include <sstream>

#include "core/base/stopwatch.h"

namespace zomeify {

std::vector<int> nearest_first(int p, int lo, int hi)
{
    std::vector<int> order;
    if (p >= lo && p <= hi)
        order.push_back(p);
    for (int d = 1; p + d <= hi || p - d >= lo; ++d)
    {
        if (p + d >= lo && p + d <= hi)
            order.push_back(p + d);
        if (p - d >= lo && p - d <= hi)
            order.push_back(p - d);
    }
    return order;
}

AdvisorResult advise_resolution(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                                const AdvisorOptions& options)
{
    Stopwatch clock;
    AdvisorResult result;
    result.surface_genus = surface_genus;
    InitialModelOptions trial_options = options.initial;
    trial_options.b1 = 0.0;
    trial_options.target_genus = surface_genus;
    const int lo = std::max(1, options.min_resolution), hi = options.max_resolution;
    for (int i = 0; i <= hi - lo; ++i)
    {
        const int n = options.downward ? hi - i : lo + i;
        trial_options.resolution = n;
        const InitialModel z0 = build_initial_model(surface, inside, trial_options);
        result.trials.push_back(
            {n, z0.report.valid, z0.report.topology.genus, z0.report.seconds, z0.model.nodes.size()});
        if (z0.report.valid && z0.report.topology.genus == surface_genus)
        {
            result.found = true;
            result.resolution = n;
            break;
        }
    }
    result.seconds = clock.seconds();
    return result;
}

namespace {

std::string handles(long long n) { return n == 1 ? "the handle" : "the " + std::to_string(n) + " handles"; }

} // namespace

std::string advice_message(int resolution, long long genus, const AdvisorResult& advice, int searched_from,
                           int searched_to)
{
    std::ostringstream os;
    const long long want = advice.surface_genus;
    os << "at " << resolution << " cells ";
    if (genus < want)
    {
        const long long lost = want - genus;
        if (genus == 0)
            os << handles(want) << " of this shape " << (want == 1 ? "closes" : "close") << " up";
        else
            os << lost << " of the " << want << " handles of this shape " << (lost == 1 ? "closes" : "close") << " up";
    }
    else
    {
        os << "the model has " << genus - want << " handle" << (genus - want == 1 ? "" : "s")
           << " more than this shape (parts that nearly touch merge)";
    }
    if (advice.found)
    {
        os << "; " << advice.resolution << (want == 0 ? " keeps the genus" : (want == 1 ? " keeps it" : " keeps them"));
        if (advice.resolution < resolution)
            os << " (a coarser grid happens to fit: genus is not monotone in the resolution)";
    }
    else if (searched_to > searched_from)
    {
        os << "; no grid from " << searched_from << " to " << searched_to << " cells keeps "
           << (want == 0 ? "the shape without handles" : (want == 1 ? "it" : "them"));
    }
    return os.str();
}

GenusAdvice genus_advice(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                         int resolution, long long genus, const InitialModelOptions& initial)
{
    if (genus == surface_genus)
        return {};
    // The user wants about this much detail: the nearest grid that keeps the genus, not the smallest
    // one overall (which may be a useless blob).
    InitialModelOptions trial = initial;
    trial.b1 = 0.0;
    trial.target_genus = surface_genus;
    AdvisorResult found;
    found.surface_genus = surface_genus;
    int from = resolution, to = resolution; // every grid in between was tried
    for (int n : nearest_first(resolution, 4, std::max(kAdviceMaxResolution, resolution + 8)))
    {
        if (n == resolution)
            continue;
        trial.resolution = n;
        const InitialModel z0 = build_initial_model(surface, inside, trial);
        found.trials.push_back(
            {n, z0.report.valid, z0.report.topology.genus, z0.report.seconds, z0.model.nodes.size()});
        from = std::min(from, n);
        to = std::max(to, n);
        if (z0.report.valid && z0.report.topology.genus == surface_genus)
        {
            found.found = true;
            found.resolution = n;
            break;
        }
    }
    return {advice_message(resolution, genus, found, from, to), found.found ? found.resolution : 0};
}

} // namespace zomeify
