#pragma once
//! \file energy_samples.h
//! The per-sample formulas of the energy (paper §4 as corrected by design.md §3.3), shared by the
//! full evaluation and the incremental one, so both see bit-identical sample values.
//!
//! Sample values are summed in fixed point: each value is rounded once to a multiple of
//! kEnergyQuantum = 2⁻³² and the integers are added exactly in 128 bits. Sums are then independent
//! of the order of addition, so the sums kept incrementally over millions of commits stay equal,
//! bit for bit, to those of a fresh evaluation (no floating-point drift).

#include <cstdint>

#include "core/anneal/energy/energy_options.h"
#include "core/anneal/energy/lattice_sum.h"
#include "core/anneal/energy/surface_context.h"

namespace zomeify {

//! The value of one integer unit of the fixed-point sums.
inline constexpr double kEnergyQuantum = 0x1p-32;
//! Sample values are capped here before rounding (d ≈ 5000·b0 for an inside sample) so that a
//! rounded value always fits 62 bits.
inline constexpr double kEnergySampleCap = 0x1p30;

//! One sample value in quanta.
using EnergyFixed = int64_t;
//! A sum of sample values in quanta (128 bits: no overflow for any realistic count).
__extension__ using EnergyAccumulator = __int128;

//! round(value / kEnergyQuantum) (halves away from zero), with value clamped to
//! [0, kEnergySampleCap] (NaN counts as the cap). Inline and without std::llround: wasm has no
//! rounding instruction for it, and a libc call per sample cost ~1% of the annealer's time there.
inline EnergyFixed quantize(double value) noexcept
{
    // `!(value < cap)` also catches NaN.
    if (!(value < kEnergySampleCap))
    {
        value = kEnergySampleCap;
    }
    if (!(value > 0.0))
    {
        return 0;
    }
    // Scaling by a power of two is exact, and so is x − trunc(x) for 0 < x < 2⁶²: the result is
    // llround's, bit for bit.
    const double x = value / kEnergyQuantum;
    const auto whole = static_cast<EnergyFixed>(x);
    return whole + (x - static_cast<double>(whole) >= 0.5 ? 1 : 0);
}

//! The forbidden zone F(d) of energy_options.h for a distance d in b0 units.
double forbidden_zone(double d, const ForbiddenZone& zone) noexcept;

//! Distance sample: d²·(1 + F(d)) with d² = sample.distance_squared and the zone of its side.
double distance_value(const SurfaceSample& sample, const EnergyOptions& options) noexcept;

//! Tangential orientation of a strut with vector d: (dᵀn)² / ‖d‖², with n the surface normal at
//! π(midpoint). In [0, 1]; 0 when the strut lies in the tangent plane.
double tangential_value(const Vec3& d, const Vec3& n) noexcept;

//! Normal orientation of the corner b of a face with corners a, b, c counter-clockwise seen from
//! outside, given to_next = c − b and to_prev = a − b:
//!   (1 − n(π(b))ᵀ n_b)²,  n_b = (c − b) × (a − b) / ‖(c − b) × (a − b)‖,
//! the unit outward corner normal. In [0, 4] (the energy divides the sum by 4C). A straight corner
//! (c − b parallel to a − b, e.g. a node on a straight chain of struts) has no normal and counts as
//! n_b ⟂ n, i.e. the value 1.
double corner_value(const Vec3& to_next, const Vec3& to_prev, const Vec3& n) noexcept;

//! Whether a face with outward (Newell) normal `face_normal` faces against the surface normal at
//! π(barycentre): a fold-over (design.md §6; paper §6: fold-overs are what the energy must avoid).
inline bool is_fold_over(const Vec3& face_normal, const Vec3& surface_normal) noexcept
{
    return face_normal.dot(surface_normal) < 0.0;
}

//! Fairing of a node p with ring p_1..p_k, from excess = k·p − Σ p_i (exact):
//! ‖p − (1/k) Σ p_i‖² = ‖excess / k‖² in b0². A node without neighbours counts 0.
double fairing_value(const LatticeSum& excess, int k) noexcept;

} // namespace zomeify
