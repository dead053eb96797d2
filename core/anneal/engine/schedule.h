#pragma once
//! \file schedule.h
//! The annealer's cooling schedule and Metropolis test (design.md §3.5, paper §5.2).
//!
//! Both are computed from +, −, ×, ÷, floor and exact power-of-two scaling only (no libm exp/log,
//! whose last bits differ between glibc natively and musl in wasm), so one thread with a fixed
//! seed takes the same decisions on every platform. This file's .cpp is compiled with
//! -ffp-contract=off so no fused multiply-add changes a rounding.

namespace zomeify {

//! e^x to about 1 ulp, bit-identical on every IEEE-754 platform. 0 below −745, +∞ above 709.7,
//! NaN for NaN.
double portable_exp(double x) noexcept;
//! ln x to about 1 ulp for finite x > 0, bit-identical on every IEEE-754 platform; −∞ for 0,
//! NaN for negative or NaN input, +∞ for +∞.
double portable_log(double x) noexcept;

//! T(x) = T0 · (T_min/T0)^x for the used fraction x ∈ [0, 1] of the budget: geometric cooling
//! (paper: T_t = T0·α^t) whose rate makes T reach T_min exactly at the end of the budget.
class CoolingSchedule
{
public:
    //! T0 ≤ T_min (e.g. no valid proposal to estimate T0 from) gives the constant T_min.
    CoolingSchedule(double t0, double t_min) noexcept;
    double temperature(double fraction) const noexcept;
    double initial() const noexcept { return t0_; }
    double minimum() const noexcept { return t_min_; }

private:
    double t0_, t_min_;
    double log_ratio_; //!< ln(T_min / T0) ≤ 0
};

//! Metropolis: accept if ΔE ≤ 0, else with probability e^(−ΔE/T): accept iff u < e^(−ΔE/T),
//! u uniform in [0, 1). T ≤ 0 accepts only ΔE ≤ 0. NaN ΔE is rejected.
bool metropolis_accept(double delta_energy, double temperature, double u) noexcept;

//! The stdev of the sampled ΔE (T0 is a factor of it, paper §5.3) from running sums, computed by Welford's
//! method in the order the samples came.
class DeltaSpread
{
public:
    void add(double delta_energy) noexcept;
    int count() const noexcept { return count_; }
    double stdev() const noexcept; //!< population stdev; 0 with fewer than 2 samples
private:
    int count_ = 0;
    double mean_ = 0.0, m2_ = 0.0;
};

} // namespace zomeify
