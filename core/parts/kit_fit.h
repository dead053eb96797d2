#pragma once
//! \file kit_fit.h
//! Whether a model fits the kits a person owns, and how many balls a model may have so that it
//! probably does. A fit is judged part by part: every ball and every strut kind (colour and length)
//! no more than the kits hold. Before a run only an estimate exists (a typical annealed model's
//! strut mix per ball), so the ball budget keeps a margin and the result is checked again.

#include <array>
#include <string>

#include "core/parts/kits.h"
#include "core/parts/parts_list.h"

namespace zomeify {

//! The margin a ball budget keeps below what the typical mix says fits (the strut mix of annealed
//! models varies by about this much from shape to shape).
inline constexpr double kKitFitMargin = 0.15;

//! The parts of a typical finished model of `balls` balls: 2.7 struts per ball in the mix of the
//! bunny annealed at 11 cells for 30 s (the page's estimate and the CLI's use the same mix).
PartsList typical_parts(size_t balls);

//! What annealing adds to Z0's parts, at most, per strut colour (blue, yellow, red) and for the balls:
//! the kits named before a run are planned for Z0's parts plus these margins, so that they hold the
//! finished model. Measured on the ten shared meshes with default runs (tests/bench/kit_estimate.sh,
//! the table in docs/page.md); tests/bench/kit_estimate.py keeps a copy.
inline constexpr std::array<double, 4> kEstimateMargins = {0.25, 0.25, 0.25, 0.10};

//! The parts to plan kits for before a run: Z0's parts, each colour and the balls raised by its
//! margin (rounded up).
PartsList estimate_parts(const PartsList& z0, const std::array<double, 4>& margins = kEstimateMargins);

//! Every count of `need` at most the same count of `have`.
bool fits(const PartCounts& need, const PartCounts& have);

//! The most balls a typical model may have with its parts inside `have`, less `margin` (0..0.9).
size_t balls_that_fit(const PartCounts& have, double margin = kKitFitMargin);

//! After a result with `need` (of `balls` balls) missed `have`: the ball budget for another try,
//! scaled by the scarcest part's have/need and less `margin`; always below `balls`.
size_t shrunk_ball_budget(const PartCounts& need, const PartCounts& have, size_t balls, double margin = 0.05);

//! "fits your kits" or "missing with your kits: 12 R1, 3 balls".
std::string fit_text(const PartCounts& need, const PartCounts& have);

} // namespace zomeify
