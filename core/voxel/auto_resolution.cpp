#include "core/voxel/auto_resolution.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "core/base/stopwatch.h"
#include "core/zome/real_sizes.h"

namespace zomeify {

namespace {

std::string holes(long long genus)
{
    return genus == 1 ? "the hole through it" : "its " + std::to_string(genus) + " holes";
}

std::string size_text(double cm)
{
    std::ostringstream os;
    if (cm >= 100.0)
        os << std::fixed << std::setprecision(2) << cm / 100.0 << " m";
    else
        os << std::lround(cm) << " cm";
    return os.str();
}

// "from 9 to 12 cells" or "at 9 cells".
std::string range_text(int from, int to)
{
    return from == to ? "at " + std::to_string(from) + " cells"
                      : "from " + std::to_string(from) + " to " + std::to_string(to) + " cells";
}

std::string explain(const AutoResolution& r)
{
    std::ostringstream os;
    os << r.resolution << " cells (" << r.balls << " balls, aiming at " << r.target_nodes << "; about "
       << size_text(r.size_cm) << "): ";
    const int p = r.preferred;
    std::string gaps;
    if (r.gap_resolution > p)
    {
        std::ostringstream g;
        g << "parts of the shape face each other across gaps narrower than a cell of the default " << p << " cells ("
          << std::lround(100.0 * r.narrow_at_preferred) << "% of its surface), so the grid is at least "
          << r.gap_resolution << " cells, where most of them get a cell between them";
        gaps = g.str();
    }
    if (!r.genus_kept)
    {
        os << "no grid " << range_text(r.searched_from, r.searched_to) << " keeps " << holes(r.surface_genus)
           << (r.genus > r.surface_genus ? " (parts of the shape nearly touch and merge)"
                                         : " (parts of the shape are thinner than a strut can follow)")
           << "; the model will have "
           << (r.genus == 0 ? "no hole" : std::to_string(r.genus) + (r.genus == 1 ? " hole" : " holes"));
        return os.str();
    }
    if (!gaps.empty())
    {
        os << gaps;
        if (r.resolution != r.gap_resolution)
            os << "; " << r.resolution << " is the nearest that keeps " << holes(r.surface_genus) << " (none "
               << (r.resolution > r.gap_resolution ? range_text(r.gap_resolution, r.resolution - 1)
                                                   : range_text(r.resolution + 1, r.searched_to))
               << " does)";
        else if (r.surface_genus > 0)
            os << ", and it keeps " << holes(r.surface_genus);
        for (const ResolutionTrial& t : r.trials)
            if (t.resolution == p && t.size_cm > 0.0)
                os << " (the default would be about " << size_text(t.size_cm) << ")";
        return os.str();
    }
    if (r.resolution == p)
        return os.str() + "the default size" + (r.surface_genus == 0 ? "" : ", which keeps " + holes(r.surface_genus));
    const bool larger = r.resolution > p;
    os << "the grid nearest the default " << p << " cells that keeps " << holes(r.surface_genus) << " (none "
       << (larger ? range_text(r.searched_from, r.resolution - 1) : range_text(r.resolution + 1, r.searched_to))
       << " does), so the model is " << (larger ? "larger" : "smaller") << " than the default";
    // The default grid's own size, for what keeping the holes costs.
    for (const ResolutionTrial& t : r.trials)
        if (t.resolution == p && t.size_cm > 0.0)
            os << " (about " << size_text(t.size_cm) << ")";
    return os.str();
}

} // namespace

size_t target_balls(size_t z0_balls, const AutoResolutionOptions& options)
{
    const auto more = static_cast<size_t>(std::lround(options.target_ratio * static_cast<double>(z0_balls)));
    return std::max(z0_balls, std::min(more, options.max_target));
}

double z0_built_size_cm(const ZomeModel& z0)
{
    if (z0.nodes.empty())
        return 0.0;
    double extent = 0.0; // b0
    for (int k = 0; k < 3; ++k)
    {
        double lo = 1e300, hi = -1e300;
        for (const ZVec& v : z0.nodes)
        {
            const double x = v.twice(k).to_double() / 2.0;
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
        extent = std::max(extent, hi - lo);
    }
    return (extent * kMmPerB0 + kBallDiameterMm) / 10.0;
}

AutoResolution choose_resolution(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                                 const AutoResolutionOptions& options)
{
    Stopwatch clock;
    const int lo = std::max(2, options.min_resolution);
    const int hi = std::max(lo, options.max_resolution);
    const int preferred = std::clamp(options.preferred_resolution, lo, hi);
    AutoResolution r;
    r.surface_genus = surface_genus;
    r.preferred = preferred;
    r.gap_resolution = preferred;
    const auto box = bounding_box(surface);
    const double longest = (box[1] - box[0]).maxCoeff();
    if (options.narrow_fraction)
    {
        r.narrow_at_preferred = options.narrow_fraction(longest / preferred);
        if (r.narrow_at_preferred > options.max_narrow_fraction)
            for (int n = preferred + 1; n <= std::min(hi, options.max_gap_resolution); ++n)
                if (options.narrow_fraction(longest / n) <= options.max_narrow_fraction)
                {
                    r.gap_resolution = n;
                    break;
                }
    }
    // From a finer start, finer grids first: a coarser one would merge the parts again.
    std::vector<int> order;
    if (r.gap_resolution > preferred)
    {
        for (int n = r.gap_resolution; n <= hi; ++n)
            order.push_back(n);
        for (int n = r.gap_resolution - 1; n >= lo; --n)
            order.push_back(n);
    }
    else
        order = nearest_first(preferred, lo, hi);
    r.searched_from = r.searched_to = order.front();
    InitialModelOptions trial = options.initial;
    trial.b1 = 0.0;
    trial.target_genus = surface_genus;
    // Z0 at the grid taken: the first that keeps the genus, else the valid grid nearest the preferred one.
    std::optional<InitialModel> taken;
    for (int n : order)
    {
        trial.resolution = n;
        InitialModel z0 = build_initial_model(surface, inside, trial);
        const InitialModelReport& z = z0.report;
        r.trials.push_back(
            {n, z.valid, z.topology.genus, z.seconds, z0.model.nodes.size(), z0_built_size_cm(z0.model)});
        r.searched_from = std::min(r.searched_from, n);
        r.searched_to = std::max(r.searched_to, n);
        const bool kept = z.valid && z.topology.genus == surface_genus;
        if (kept || (z.valid && !taken))
        {
            r.resolution = n;
            r.genus_kept = kept;
            taken = std::move(z0);
        }
        if (kept)
            break;
    }
    if (!taken)
    {
        r.resolution = preferred; // no grid became manifold: the run says so when it builds Z0
    }
    else
    {
        r.balls = taken->model.nodes.size();
        r.struts = taken->model.struts.size();
        r.genus = taken->report.topology.genus;
        r.size_cm = z0_built_size_cm(taken->model);
        r.target_nodes = target_balls(r.balls, options);
    }
    r.seconds = clock.seconds();
    r.message = explain(r);
    return r;
}

} // namespace zomeify
