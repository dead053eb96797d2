#pragma once
//! \file qphi.h
//! Exact numbers a + b·φ of the ring Z[φ], φ = (1 + √5)/2, with overflow-checked arithmetic.
//! φ² = φ + 1 and 1/φ = φ − 1 keep every product and every φ-scaling inside Z[φ].

#include <cstdint>
#include <iosfwd>

#include "core/base/errors.h"

namespace zomeify {

inline constexpr double kPhi = 1.6180339887498948482;

namespace detail {
[[noreturn]] void throw_overflow();

inline int64_t checked_add(int64_t x, int64_t y)
{
    int64_t r;
    if (__builtin_add_overflow(x, y, &r))
        throw_overflow();
    return r;
}
inline int64_t checked_sub(int64_t x, int64_t y)
{
    int64_t r;
    if (__builtin_sub_overflow(x, y, &r))
        throw_overflow();
    return r;
}
inline int64_t checked_mul(int64_t x, int64_t y)
{
    int64_t r;
    if (__builtin_mul_overflow(x, y, &r))
        throw_overflow();
    return r;
}
} // namespace detail

//! The exact number a + b·φ.
struct QPhi
{
    int64_t a = 0; //!< rational (integer) part
    int64_t b = 0; //!< coefficient of φ

    friend bool operator==(const QPhi&, const QPhi&) = default;

    QPhi operator+(QPhi o) const { return {detail::checked_add(a, o.a), detail::checked_add(b, o.b)}; }
    QPhi operator-(QPhi o) const { return {detail::checked_sub(a, o.a), detail::checked_sub(b, o.b)}; }
    QPhi operator-() const { return QPhi{} - *this; }
    //! (a + bφ)(c + dφ) = (ac + bd) + (ad + bc + bd)φ, using φ² = φ + 1.
    QPhi operator*(QPhi o) const
    {
        using namespace detail;
        const int64_t bd = checked_mul(b, o.b);
        return {checked_add(checked_mul(a, o.a), bd),
                checked_add(checked_add(checked_mul(a, o.b), checked_mul(b, o.a)), bd)};
    }
    //! Multiplication by φ: (a + bφ)φ = b + (a + b)φ.
    QPhi times_phi() const { return {b, detail::checked_add(a, b)}; }
    //! Division by φ: (a + bφ)(φ − 1) = (b − a) + aφ.
    QPhi div_phi() const { return {detail::checked_sub(b, a), a}; }

    //! Exact sign: −1, 0 or +1.
    int sign() const;
    double to_double() const { return static_cast<double>(a) + static_cast<double>(b) * kPhi; }
    bool is_zero() const { return a == 0 && b == 0; }
    bool both_even() const { return (a % 2 == 0) && (b % 2 == 0); }
};

//! Exact ordering by value (not lexicographic).
int compare(QPhi x, QPhi y);

//! φ^n for n ≥ 0 or n < 0.
QPhi phi_power(int n);

//! Writes "a+bφ" for diagnostics.
std::ostream& operator<<(std::ostream& os, QPhi q);

} // namespace zomeify
