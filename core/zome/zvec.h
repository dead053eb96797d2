#pragma once
//! \file zvec.h
//! Exact points and vectors of the Zome lattice in the 6-integer form of design.md §2:
//! [a0..a5] means ((a0·φ + a1)/2, (a2·φ + a3)/2, (a4·φ + a5)/2), in units where b0 = 1.
//! Sums, differences, comparison and hashing are exact integer operations.

#include <array>
#include <cstddef>
#include <cstdint>
#include <iosfwd>

#include "core/zome/qphi.h"

namespace zomeify {

struct ZVec
{
    //! c[2k] is the φ-coefficient and c[2k+1] the integer coefficient of twice component k.
    std::array<int32_t, 6> c{};

    friend bool operator==(const ZVec&, const ZVec&) = default;
    //! Lexicographic order of the six integers (a total order for containers, not geometric).
    //! Written out because libc++ 14 (Emscripten 3.1.6) has no operator<=> for std::array.
    friend bool operator<(const ZVec& a, const ZVec& b) { return a.c < b.c; }

    //! Twice component k (0 = x, 1 = y, 2 = z) as an exact number.
    QPhi twice(int k) const { return {c[2 * k + 1], c[2 * k]}; }
    //! Builds a vector from twice its components; throws OverflowError if they leave int32.
    static ZVec from_twice(QPhi x2, QPhi y2, QPhi z2);

    ZVec operator+(const ZVec& o) const;
    ZVec operator-(const ZVec& o) const;
    ZVec operator-() const;
    ZVec& operator+=(const ZVec& o) { return *this = *this + o; }
    ZVec& operator-=(const ZVec& o) { return *this = *this - o; }

    //! The vector scaled by φ (one strut size up).
    ZVec times_phi() const;
    //! The vector scaled by 1/φ (one strut size down).
    ZVec div_phi() const;

    bool is_zero() const { return c == std::array<int32_t, 6>{}; }
    //! Component k as a double.
    double coord(int k) const { return 0.5 * twice(k).to_double(); }
    std::array<double, 3> to_double() const { return {coord(0), coord(1), coord(2)}; }
};

//! 4·(u·v), exact.
QPhi dot4(const ZVec& u, const ZVec& v);
//! 4·|u|², exact.
inline QPhi norm4(const ZVec& u) { return dot4(u, u); }

//! A well-mixed 64-bit hash of the six integers (for exact position hashing).
struct ZVecHash
{
    size_t operator()(const ZVec& v) const noexcept;
};

std::ostream& operator<<(std::ostream& os, const ZVec& v);

} // namespace zomeify
