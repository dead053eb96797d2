#include "core/voxel/advisor.h"

#include <algorithm>
#include <sstream>

#include "core/base/stopwatch.h"

namespace zomeify {

AdvisorResult advise_resolution(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                                const AdvisorOptions& options)
{
    Stopwatch clock;
    AdvisorResult result;
    result.surface_genus = surface_genus;
    InitialModelOptions trial_options = options.initial;
    trial_options.b1 = 0.0;
    trial_options.target_genus = surface_genus;
    for (int n = std::max(1, options.min_resolution); n <= options.max_resolution; ++n)
    {
        trial_options.resolution = n;
        const InitialModel z0 = build_initial_model(surface, inside, trial_options);
        result.trials.push_back({n, z0.report.valid, z0.report.topology.genus, z0.report.seconds});
        if (z0.report.valid && z0.report.topology.genus == surface_genus)
        {
            result.found = true;
            result.resolution = n;
            break;
        }
        if (clock.seconds() > options.seconds)
            break;
    }
    result.seconds = clock.seconds();
    return result;
}

namespace {

std::string handles(long long n) { return n == 1 ? "the handle" : "the " + std::to_string(n) + " handles"; }

} // namespace

std::string advice_message(int resolution, long long genus, const AdvisorResult& advice)
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
    else if (!advice.trials.empty())
    {
        os << "; no resolution up to " << advice.trials.back().resolution << " keeps the genus (genus " << want << ")";
    }
    return os.str();
}

GenusAdvice genus_advice(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                         int resolution, long long genus, double seconds)
{
    if (genus == surface_genus)
        return {};
    // The user wants about this much detail, so look first for the nearest finer grid that keeps
    // the genus (the smallest one overall may be a useless blob), and only then below their choice.
    AdvisorOptions advisor;
    advisor.seconds = seconds;
    advisor.min_resolution = resolution + 1;
    advisor.max_resolution = std::max(kAdviceMaxResolution, 2 * resolution);
    AdvisorResult found = advise_resolution(surface, surface_genus, inside, advisor);
    if (!found.found && resolution > 4)
    {
        advisor.min_resolution = 4;
        advisor.max_resolution = resolution - 1;
        const AdvisorResult below = advise_resolution(surface, surface_genus, inside, advisor);
        if (below.found)
            found = below;
    }
    return {advice_message(resolution, genus, found), found.found ? found.resolution : 0};
}

} // namespace zomeify
