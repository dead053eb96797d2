#pragma once
//! \file energy_sums.h
//! The global sums and counts the energy is made of (design.md §3.3: every term is an average, so
//! a change alters both), the terms computed from them, and the exact energy change between two
//! sets of sums.

#include <cstdint>

#include "core/anneal/energy/energy_options.h"
#include "core/anneal/energy/energy_samples.h"

namespace zomeify {

//! Fixed-point sums (in units of kEnergyQuantum) and counts. The same type describes a change
//! (signed differences of every field).
struct EnergySums
{
    EnergyAccumulator distance = 0;   //!< Σ d²(1 + F(d)) over nodes, strut midpoints, face barycentres
    EnergyAccumulator tangential = 0; //!< Σ (dᵀn)²/‖d‖² over struts
    EnergyAccumulator normal = 0;     //!< Σ (1 − nᵀn_b)² over face corners
    EnergyAccumulator fairing = 0;    //!< Σ ‖p − mean of 1-ring‖² over nodes
    EnergyAccumulator surface = 0;    //!< Σ d²(1 + F(d)) over the points of S, d = distance to the model's faces
    int64_t nodes = 0;                //!< N
    int64_t struts = 0;               //!< S
    int64_t faces = 0;                //!< F
    int64_t corners = 0;              //!< C (sum of face sizes)
    int64_t surface_samples = 0;      //!< M, the points of S (fixed: a change's delta leaves it 0)
    int64_t fold_overs = 0;           //!< faces turned against S's normal at their barycentre

    //! P = N + S + F, the number of distance samples.
    int64_t samples() const noexcept { return nodes + struts + faces; }

    EnergySums& operator+=(const EnergySums& d) noexcept;
    EnergySums& operator-=(const EnergySums& d) noexcept;
    friend EnergySums operator+(EnergySums a, const EnergySums& b) noexcept { return a += b; }
    friend EnergySums operator-(EnergySums a, const EnergySums& b) noexcept { return a -= b; }
    friend bool operator==(const EnergySums&, const EnergySums&) = default;
};

//! Every term of the energy (paper §4, design.md §3.3) with the sums it comes from:
//!   E_dist    = Σ d²(1 + F(d)) / P                     (b0 = 1, so d_norm² = 1)
//!   E_tan     = Σ_struts (dᵀ n(π(m)))² / ‖d‖² / S
//!   E_normal  = Σ_corners (1 − n(π(b))ᵀ n_b)² / (4C)
//!   E_orient  = 0.25·E_tan + 0.75·E_normal
//!   E_fair    = Σ_nodes ‖p − mean of 1-ring‖² / N
//!   E_complex = (N − N_target)² / N_target
//!   E_surface = Σ_points of S d²(1 + F(d)) / M   (d: distance to the nearest face, capped)
//!   E         = 10·E_dist + 100·E_orient + 5·E_fair + 1·E_complex + w_s·E_surface
//!               + w_fold·(fold-over faces)   (EnergyOptions' weights)
//! An average over no samples counts 0.
struct EnergyTerms
{
    EnergySums sums;
    double distance = 0.0;
    double tangential = 0.0;
    double normal = 0.0;
    double orientation = 0.0;
    double fairing = 0.0;
    double complexity = 0.0;
    double surface = 0.0;
    double fold_overs = 0.0; //!< their number
    double total = 0.0;      //!< the weighted sum E
};

//! The terms of a set of sums.
EnergyTerms energy_terms(const EnergySums& sums, const EnergyOptions& options) noexcept;

//! E(base + delta) − E(base), computed per term from the exact integer differences
//! ((ΔS·n − S·Δn) / (n·(n + Δn)) for an average), so it is accurate relative to the change itself
//! rather than to E.
double energy_change(const EnergySums& base, const EnergySums& delta, const EnergyOptions& options) noexcept;

//! A fixed-point sum as a double (in the energy's units).
inline double to_double(EnergyAccumulator sum) noexcept { return static_cast<double>(sum) * kEnergyQuantum; }

} // namespace zomeify
