#pragma once
//! \file exact_steps.h
//! Exact lattice steps for the operators, without exceptions (propose() is noexcept; ZVec's
//! operators throw on int32 overflow, which a hostile model far from the origin could reach), and
//! the table look-ups that give new positions (paper §5.1 "Generating an Operation").
//!
//! Internal to core/anneal/operators.

#include <optional>

#include "core/anneal/random.h"
#include "core/zome/zvec.h"

namespace zomeify::detail {

//! a + b, or nullopt on overflow.
std::optional<ZVec> checked_add(const ZVec& a, const ZVec& b) noexcept;
//! The Zome vector id of to − from, or −1 (not a Zome vector, or overflow).
int vector_between(const ZVec& from, const ZVec& to) noexcept;

//! SPLITVECTOR: a random (v*, v') with v* + v' = vector `id`; the new node is start + v*.
std::optional<ZVec> split_position(const ZVec& start, int id, Rng& rng) noexcept;
//! CHANGEDIRECTIONS: for the path start →(a) middle →(b) end, a random other pair (w*, w') with
//! w* + w' = a + b; the new node is start + w* (the middle moved between the two struts).
std::optional<ZVec> change_position(const ZVec& start, int a, int b, Rng& rng) noexcept;

} // namespace zomeify::detail
