#pragma once
//! \file portable_math.h
//! Elementary functions from +, −, ×, ÷ and sqrt only, which IEEE 754 rounds the same way on every
//! platform. glibc's and musl's (Emscripten's) libm differ in the last bit of atan2 and friends;
//! whatever feeds the energy must give the same bits natively and in wasm.

#include <cmath>

namespace zomeify {

//! atan2(y, x) for y ≥ 0, in [0, π]; (0, 0) gives 0. Within a few ulp of the correctly rounded
//! value (tests/geom/portable_math_test.cpp).
inline double portable_angle(double y, double x) noexcept
{
    constexpr double kPi = 3.141592653589793238462643383279502884;
    if (!(y > 0.0))
        return x < 0.0 ? kPi : 0.0;
    // Half angle: θ = 2·atan(t), t = tan(θ/2) = y / (r + x) = (r − x) / y, whichever form has no
    // cancellation for the sign of x.
    const double r = std::sqrt(x * x + y * y);
    double t = x >= 0.0 ? y / (r + x) : (r - x) / y;
    const bool complement = t > 1.0; // atan(t) = π/2 − atan(1/t)
    if (complement)
        t = 1.0 / t;
    // atan(t) = 2·atan(t / (1 + sqrt(1 + t²))) until t ≤ 0.2, then the odd series: each term is
    // at most 0.04 of the one before, so 12 terms are below 1e-17 of the first.
    int halvings = 0;
    while (t > 0.2)
    {
        t = t / (1.0 + std::sqrt(1.0 + t * t));
        ++halvings;
    }
    const double t2 = t * t;
    double tail = 0.0; // 1/3 − t²/5 + t⁴/7 − …, by Horner from the smallest term
    for (int k = 25; k >= 3; k -= 2)
        tail = 1.0 / k - t2 * tail;
    double a = std::ldexp(t - t * t2 * tail, halvings);
    if (complement)
        a = kPi / 2 - a;
    return 2.0 * a;
}

} // namespace zomeify
