#include "core/anneal/engine/schedule.h"

#include <cmath>
#include <limits>

namespace zomeify {

namespace {

// ln 2 split so that k · kLn2High is exact for |k| < 2^11 (its low 11 bits are zero).
constexpr double kLn2High = 0x1.62e42fee00000p-1;
constexpr double kLn2Low = 0x1.a39ef35793c76p-33;
constexpr double kInvLn2 = 0x1.71547652b82fep0;

} // namespace

double portable_exp(double x) noexcept
{
    if (x != x)
        return x;
    if (x < -745.2)
        return 0.0;
    if (x > 709.78)
        return std::numeric_limits<double>::infinity();
    // x = k·ln2 + r with |r| ≤ ln2/2; e^r by its Taylor series (degree 13: error < 1e-17 there).
    const double k = std::floor(x * kInvLn2 + 0.5);
    const double r = (x - k * kLn2High) - k * kLn2Low;
    double p = 1.0 / 6227020800.0; // 1/13!
    constexpr double kInverseFactorials[] = {1.0 / 479001600.0,
                                             1.0 / 39916800.0,
                                             1.0 / 3628800.0,
                                             1.0 / 362880.0,
                                             1.0 / 40320.0,
                                             1.0 / 5040.0,
                                             1.0 / 720.0,
                                             1.0 / 120.0,
                                             1.0 / 24.0,
                                             1.0 / 6.0,
                                             0.5,
                                             1.0,
                                             1.0};
    for (double c : kInverseFactorials)
        p = p * r + c;
    // ldexp is exact (a power-of-two scaling; subnormal results round by IEEE rules).
    return std::ldexp(p, static_cast<int>(k));
}

double portable_log(double x) noexcept
{
    if (x != x || x < 0.0)
        return std::numeric_limits<double>::quiet_NaN();
    if (x == 0.0)
        return -std::numeric_limits<double>::infinity();
    if (x == std::numeric_limits<double>::infinity())
        return x;
    int e = 0;
    double m = std::frexp(x, &e); // x = m·2^e, m ∈ [0.5, 1), exact
    if (m < 0.70710678118654752)
    {
        m *= 2.0;
        --e;
    }
    // ln m = 2·atanh(s) with s = (m − 1)/(m + 1), |s| ≤ 0.1716: the odd series to s^25.
    const double s = (m - 1.0) / (m + 1.0);
    const double s2 = s * s;
    double series = 1.0 / 25.0;
    for (int n = 23; n >= 1; n -= 2)
        series = series * s2 + 1.0 / n;
    const double log_m = 2.0 * s * series;
    const double k = static_cast<double>(e);
    return (k * kLn2High + log_m) + k * kLn2Low;
}

CoolingSchedule::CoolingSchedule(double t0, double t_min) noexcept
    : t0_(t0 > t_min ? t0 : t_min), t_min_(t_min), log_ratio_(t0 > t_min ? portable_log(t_min / t0) : 0.0)
{
}

double CoolingSchedule::temperature(double fraction) const noexcept
{
    if (!(fraction > 0.0))
        return t0_;
    if (fraction >= 1.0)
        return t_min_;
    return t0_ * portable_exp(fraction * log_ratio_);
}

bool metropolis_accept(double delta_energy, double temperature, double u) noexcept
{
    if (delta_energy <= 0.0)
        return true;
    if (!(delta_energy > 0.0) || !(temperature > 0.0))
        return false; // NaN, or frozen
    return u < portable_exp(-delta_energy / temperature);
}

void DeltaSpread::add(double delta_energy) noexcept
{
    if (!std::isfinite(delta_energy))
        return;
    ++count_;
    const double d = delta_energy - mean_;
    mean_ += d / count_;
    m2_ += d * (delta_energy - mean_);
}

double DeltaSpread::stdev() const noexcept { return count_ < 2 ? 0.0 : std::sqrt(m2_ / count_); }

} // namespace zomeify
