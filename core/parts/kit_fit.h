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

//! The parts of a finished default run (30 s) from a Z0 of `balls` balls, as the median of the ten
//! shared meshes per strut kind (tests/bench/kit_estimate.sh; the table is in docs/page.md): the
//! typical end of the kits named before a run. The mix varies a lot with the shape (yellow Y1 from
//! 0.47 to 1.0 per ball), so this is no bound; the safe end is Z0's own parts (see below).
PartsList annealed_parts(size_t balls);

//! Annealing never needed more than Z0's own parts: Z0 is all B1 (two per ball), the runs measured
//! keep 34–100% of them, and the kits that hold Z0 hold 1.33 yellow and 0.8 red struts of each
//! length per ball, more than any finished model measured (at most 1.01 and 0.22). So the kits
//! planned for Z0's parts are the ones a buyer can trust before the run.

//! Z0's own parts scaled to a model of `balls` balls (rounded up; unchanged when `balls` is not more
//! than Z0's): the safe end of a kit estimate when the annealer is asked for more balls than Z0 has,
//! as the automatic choice does (auto_resolution.h), since the kits that hold Z0 hold more of every
//! strut per ball than a finished model needs.
PartsList parts_for_balls(const PartsList& z0_parts, size_t balls);

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
