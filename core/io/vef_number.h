#pragma once
//! \file vef_number.h
//! Numbers as vZome's VEF writes them for the golden field: `(a,b)` = a·φ + b, each factor an
//! integer or a fraction `p/q` (older vZome wrote `(8/2,4/2)`, newer ones `(1/2,3)`), a plain
//! rational `b` or `p/q`, and `(f5,…,f2,a,b)` from fields whose first two irrationals are 1 and φ
//! (the extra factors must then be zero). Exact, overflow-checked (OverflowError).

#include <cstdint>
#include <string>
#include <string_view>

#include "core/zome/qphi.h"

namespace zomeify {

//! The exact number (n.a + n.b·φ) / d, kept reduced with d > 0.
struct GoldenFraction
{
    QPhi n;
    int64_t d = 1;

    bool is_integral() const { return d == 1; }
    GoldenFraction operator+(const GoldenFraction& o) const;
    GoldenFraction operator-(const GoldenFraction& o) const;
    GoldenFraction operator*(const GoldenFraction& o) const;
    friend bool operator==(const GoldenFraction&, const GoldenFraction&) = default;
};

//! Parses one VEF number. `rational_only` (the file said `field rational`) refuses parentheses.
//! Throws InvalidInputError naming `what` on anything else.
GoldenFraction parse_vef_number(std::string_view token, bool rational_only, const std::string& what);

} // namespace zomeify
