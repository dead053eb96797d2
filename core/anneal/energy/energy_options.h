#pragma once
//! \file energy_options.h
//! Weights and parameters of the annealer's energy (paper §4, design.md §3.3).

#include <cstddef>

namespace zomeify {

//! One forbidden zone (paper §4.1). With d the distance of a sample to S in b0 units:
//!   F(d) = 0                                            for d ≤ d_min,
//!   F(d) = f_max · ((d − d_min) / (d_max − d_min))²     for d_min < d < d_max,
//!   F(d) = f_max                                        for d ≥ d_max,
//! so F is continuous, quadratic between the breakpoints, and F(d_max) = f_max. A sample then
//! costs d² · (1 + F(d)).
struct ForbiddenZone
{
    double d_min = 1.0 / 3.0; //!< b0 units
    double d_max = 1.5;       //!< b0 units, > d_min
    double f_max = 35.0;
};

//! E = w_distance·E_dist + w_orientation·E_orient + w_fairing·E_fair + w_complexity·E_complex
//!     + w_surface·E_surface + w_fold·(number of fold-over faces).
struct EnergyOptions
{
    //! The paper's weights are 10, 100, 5, 1 (§4, design §3.3; paper_energy()); E_dist counts 3×
    //! the paper's here, which with E_surface brings the model closer to S both ways (engine
    //! README, "Energy").
    double w_distance = 30.0;
    double w_orientation = 100.0;
    double w_fairing = 5.0;
    double w_complexity = 1.0;
    //! The surface's distance to the model (surface_distance.h; not in the paper, whose energy is
    //! this one with w_surface = 0): E_dist measures how far the model is from S, never how far S
    //! is from the model, so without it a model may leave thin parts of S behind.
    double w_surface = 100.0;
    //! Spacing of the points on S that E_surface measures from (b0 units).
    double surface_spacing = 0.5;
    //! A point of S farther than this from every face counts as this far (b0 units), so a change
    //! only alters the points within this reach of the faces it removes or adds.
    double surface_cap = 0.75;
    //! A point's value is d²·(1 + F(d)) with this zone (f_max = 0: plain d²).
    ForbiddenZone surface_zone{0.25, 1.0, 0.0};
    //! Energy per fold-over face (a face turned against the surface normal at its barycentre).
    //! No commit may add one; this makes removing those of the starting model pay.
    double w_fold = 1.0;

    //! Samples inside S: d_min = b0/3, d_max = 1.5·b0, F_max = 35 (penalises the interior most).
    ForbiddenZone inside{1.0 / 3.0, 1.5, 35.0};
    //! Samples outside S (or on it): d_min = b0/3, d_max = 2.5·b0, F_max = 15.
    ForbiddenZone outside{1.0 / 3.0, 2.5, 15.0};

    //! Weights of the tangential (strut) and normal (corner) parts of E_orient.
    double tangential_share = 0.25;
    double normal_share = 0.75;

    //! N_target of E_complex = (N − N_target)² / N_target. Must be > 0 when w_complexity ≠ 0; the
    //! annealer sets it to N0, the node count of Z0, unless the user asks for another target.
    size_t target_nodes = 0;
};

//! The paper's energy exactly (§4, design.md §3.3): its weights, no E_surface, no fold-over term.
inline EnergyOptions paper_energy() noexcept
{
    EnergyOptions o;
    o.w_distance = 10.0;
    o.w_surface = 0.0;
    o.w_fold = 0.0;
    return o;
}

} // namespace zomeify
