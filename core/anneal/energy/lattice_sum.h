#pragma once
//! \file lattice_sum.h
//! LatticeSum: an exact sum of Zome lattice points in 64-bit integers (the six-integer form of
//! design.md §2). The energy's samples are such sums divided by a small count: a node is one point,
//! a strut midpoint is (a + b)/2, a face barycentre (a + b + c)/3 or (a + b + c + d)/4. Keeping the
//! numerator exact makes every sample, and its projection-cache key, independent of the order in
//! which its points were added, which is what lets incremental sums equal a fresh evaluation.

#include <array>
#include <cstdint>

#include "core/geom/triangle_mesh.h"
#include "core/zome/qphi.h"
#include "core/zome/zvec.h"

namespace zomeify {

struct LatticeSum
{
    //! c[2k] is the φ-coefficient and c[2k+1] the integer coefficient of twice component k.
    std::array<int64_t, 6> c{};

    friend bool operator==(const LatticeSum&, const LatticeSum&) = default;

    LatticeSum& operator+=(const ZVec& p) noexcept
    {
        for (int i = 0; i < 6; ++i)
        {
            c[i] += p.c[i];
        }
        return *this;
    }
    LatticeSum& operator-=(const ZVec& p) noexcept
    {
        for (int i = 0; i < 6; ++i)
        {
            c[i] -= p.c[i];
        }
        return *this;
    }
    //! The sum multiplied by an integer k (exact).
    LatticeSum times(int64_t k) const noexcept
    {
        LatticeSum out;
        for (int i = 0; i < 6; ++i)
        {
            out.c[i] = c[i] * k;
        }
        return out;
    }
    LatticeSum operator-(const LatticeSum& o) const noexcept
    {
        LatticeSum out;
        for (int i = 0; i < 6; ++i)
        {
            out.c[i] = c[i] - o.c[i];
        }
        return out;
    }
    //! The point sum / divisor in Zome units (b0 = 1), as doubles.
    Vec3 divided(int divisor) const noexcept
    {
        const double s = 0.5 / static_cast<double>(divisor);
        return Vec3((static_cast<double>(c[0]) * kPhi + static_cast<double>(c[1])) * s,
                    (static_cast<double>(c[2]) * kPhi + static_cast<double>(c[3])) * s,
                    (static_cast<double>(c[4]) * kPhi + static_cast<double>(c[5])) * s);
    }
    //! A well-mixed 64-bit key of (sum, divisor) for the projection cache.
    uint64_t key(int divisor) const noexcept
    {
        uint64_t h = 0x9e3779b97f4a7c15ULL ^ static_cast<uint64_t>(divisor);
        for (int64_t x : c)
        {
            h ^= static_cast<uint64_t>(x) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
            h *= 0xbf58476d1ce4e5b9ULL;
        }
        return h;
    }
};

//! The sum of one point.
inline LatticeSum lattice_sum(const ZVec& p) noexcept
{
    LatticeSum s;
    s += p;
    return s;
}

//! The exact vector b − a as doubles in Zome units.
inline Vec3 difference(const ZVec& a, const ZVec& b) noexcept
{
    LatticeSum s = lattice_sum(b);
    s -= a;
    return s.divided(1);
}

} // namespace zomeify
