#include "core/anneal/energy/energy_sums.h"

namespace zomeify {
namespace {

double average(EnergyAccumulator sum, int64_t count) noexcept
{
    return count > 0 ? to_double(sum) / static_cast<double>(count) : 0.0;
}

// Change of sum/count when the sum changes by d_sum and the count by d_count. The numerator is an
// exact integer; only the final division rounds.
double average_change(EnergyAccumulator sum, int64_t count, EnergyAccumulator d_sum, int64_t d_count) noexcept
{
    const int64_t new_count = count + d_count;
    if (count <= 0 || new_count <= 0)
    {
        return average(sum + d_sum, new_count) - average(sum, count);
    }
    const EnergyAccumulator numerator = d_sum * count - sum * d_count;
    return static_cast<double>(numerator) * kEnergyQuantum /
           (static_cast<double>(count) * static_cast<double>(new_count));
}

double complexity(int64_t nodes, const EnergyOptions& options) noexcept
{
    if (options.target_nodes == 0)
    {
        return 0.0;
    }
    const double target = static_cast<double>(options.target_nodes);
    const double excess = static_cast<double>(nodes) - target;
    return excess * excess / target;
}

} // namespace

EnergySums& EnergySums::operator+=(const EnergySums& d) noexcept
{
    distance += d.distance;
    tangential += d.tangential;
    normal += d.normal;
    fairing += d.fairing;
    surface += d.surface;
    nodes += d.nodes;
    struts += d.struts;
    faces += d.faces;
    corners += d.corners;
    surface_samples += d.surface_samples;
    fold_overs += d.fold_overs;
    return *this;
}

EnergySums& EnergySums::operator-=(const EnergySums& d) noexcept
{
    distance -= d.distance;
    tangential -= d.tangential;
    normal -= d.normal;
    fairing -= d.fairing;
    surface -= d.surface;
    nodes -= d.nodes;
    struts -= d.struts;
    faces -= d.faces;
    corners -= d.corners;
    surface_samples -= d.surface_samples;
    fold_overs -= d.fold_overs;
    return *this;
}

EnergyTerms energy_terms(const EnergySums& sums, const EnergyOptions& options) noexcept
{
    EnergyTerms t;
    t.sums = sums;
    t.distance = average(sums.distance, sums.samples());
    t.tangential = average(sums.tangential, sums.struts);
    t.normal = 0.25 * average(sums.normal, sums.corners);
    t.orientation = options.tangential_share * t.tangential + options.normal_share * t.normal;
    t.fairing = average(sums.fairing, sums.nodes);
    t.complexity = complexity(sums.nodes, options);
    t.surface = average(sums.surface, sums.surface_samples);
    t.fold_overs = static_cast<double>(sums.fold_overs);
    t.total = options.w_distance * t.distance + options.w_orientation * t.orientation + options.w_fairing * t.fairing +
              options.w_complexity * t.complexity + options.w_surface * t.surface + options.w_fold * t.fold_overs;
    return t;
}

double energy_change(const EnergySums& base, const EnergySums& delta, const EnergyOptions& options) noexcept
{
    const double d_distance = average_change(base.distance, base.samples(), delta.distance, delta.samples());
    const double d_tangential = average_change(base.tangential, base.struts, delta.tangential, delta.struts);
    const double d_normal = 0.25 * average_change(base.normal, base.corners, delta.normal, delta.corners);
    double d_complexity = 0.0;
    if (options.target_nodes != 0)
    {
        // (N' − T)² − (N − T)² = ΔN·(N + N' − 2T), exact in integers.
        const int64_t target = static_cast<int64_t>(options.target_nodes);
        const int64_t n = base.nodes;
        const int64_t dn = delta.nodes;
        d_complexity = static_cast<double>(dn * (2 * n + dn - 2 * target)) / static_cast<double>(target);
    }
    return options.w_distance * d_distance +
           options.w_orientation * (options.tangential_share * d_tangential + options.normal_share * d_normal) +
           options.w_fairing * average_change(base.fairing, base.nodes, delta.fairing, delta.nodes) +
           options.w_complexity * d_complexity +
           options.w_surface *
               average_change(base.surface, base.surface_samples, delta.surface, delta.surface_samples) +
           options.w_fold * static_cast<double>(delta.fold_overs);
}

} // namespace zomeify
