#include "core/anneal/energy/energy_samples.h"

#include <cmath>

namespace zomeify {

double forbidden_zone(double d, const ForbiddenZone& zone) noexcept
{
    if (d <= zone.d_min)
    {
        return 0.0;
    }
    if (d >= zone.d_max)
    {
        return zone.f_max;
    }
    const double t = (d - zone.d_min) / (zone.d_max - zone.d_min);
    return zone.f_max * t * t;
}

double distance_value(const SurfaceSample& sample, const EnergyOptions& options) noexcept
{
    const double d2 = sample.distance_squared;
    const ForbiddenZone& zone = sample.inside ? options.inside : options.outside;
    return d2 * (1.0 + forbidden_zone(std::sqrt(d2), zone));
}

double tangential_value(const Vec3& d, const Vec3& n) noexcept
{
    const double len2 = d.squaredNorm();
    if (!(len2 > 0.0))
    {
        return 0.0;
    }
    const double dn = d.dot(n);
    // n is unit up to rounding; the clamp keeps the documented range exactly.
    return std::fmin(dn * dn / len2, 1.0);
}

double corner_value(const Vec3& to_next, const Vec3& to_prev, const Vec3& n) noexcept
{
    const Vec3 cross = to_next.cross(to_prev);
    const double len = cross.norm();
    // Distinct Zome directions are degrees apart, so only truly parallel struts fall below this.
    if (!(len > 1e-9 * to_next.norm() * to_prev.norm()))
    {
        return 1.0;
    }
    const double dev = 1.0 - n.dot(cross) / len;
    return dev * dev;
}

double fairing_value(const LatticeSum& excess, int k) noexcept
{
    if (k <= 0)
    {
        return 0.0;
    }
    return excess.divided(k).squaredNorm();
}

} // namespace zomeify
