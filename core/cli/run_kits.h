#pragma once
//! \file run_kits.h
//! `run --have KITS [--fit-kits]`: the lines the run prints about the kits a person owns, and the
//! largest resolution "fit my kits" may choose given the scale options the user gave.

#include <string>

#include "core/cli/args.h"
#include "core/parts/kit_fit.h"
#include "core/parts/parts_report.h"

namespace zomeify::cli {

//! How many attempts --fit-kits makes before it says the result does not fit.
inline constexpr int kFitAttempts = 3;
//! The finest grid --fit-kits tries when no scale is given (a Workshop kit fits about 15 cells).
inline constexpr int kFitMaxResolution = 64;

//! "1 x Creator 3 + 2 x Basic".
std::string owned_text(const OwnedKits& owned);

//! The finest resolution --fit-kits may use: the one --resolution, --b1 or --size-cm asks for (the
//! size asked is the largest one wanted), else kFitMaxResolution.
int fit_max_resolution(const Args& args, double mesh_longest_side);

//! Before annealing: whether a model of `balls` balls typically fits `have`.
std::string estimate_fit_line(size_t balls, const PartCounts& have);

} // namespace zomeify::cli
