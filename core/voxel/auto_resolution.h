#pragma once
//! \file auto_resolution.h
//! The grid and the ball target a run uses when the user has chosen neither (issue 37), the one
//! automatic choice: `zomeify run`, `run --initial-only`, `inspect --json`, the page's estimate and
//! the advisor's range all come from here.
//!
//! Holes first, then size: the preferred grid (the default built size) is tried, then the grids
//! nearest to it (finer before coarser at equal distance) until one keeps the genus of S. When no
//! grid of the range keeps it, the preferred grid is taken and the message says so. The search is
//! bounded by the grids it may try, never by time, so every machine and the wasm build choose alike.
//! The annealer is then asked for `target_ratio` times Z0's balls, at most `max_target` (the paper's
//! lever: its 62 cm bunny has 392 balls from a Z0 of about 220), so a small model still shows the shape.

#include <functional>
#include <string>
#include <vector>

#include "core/voxel/advisor.h"

namespace zomeify {

struct AutoResolutionOptions
{
    //! The grid tried first, the default built size: 8 cells make a model about 63 cm across, the
    //! paper's bunny (core/voxel/README.md, "Automatic resolution": 8, 10 and 12 measured).
    int preferred_resolution = 8;
    int min_resolution = 6;  //!< coarser grids leave any shape a lump
    int max_resolution = 32; //!< the finest grid tried; with min_resolution, the work bound
    //! Balls asked of the annealer per ball of Z0 (RunSettings' target_nodes when the user set none),
    //! the paper's 392 / ~220: against Z0's count, a lower symmetric RMS on every shared mesh (README)...
    double target_ratio = 1.8;
    //! ...up to about the paper's bunny (4 Creator 3 kits and a Creator 1 or two), never below Z0's count.
    size_t max_target = 400;
    //! The fraction of S's area facing another part of S across a gap narrower than a width (mesh units),
    //! facing_gaps.h; unset, gaps are not looked at. Where more than `max_narrow_fraction` of S faces a
    //! part closer than a cell of the preferred grid (a knot's strands: with the genus kept they still
    //! merge into a lump), the search starts at the coarsest grid up to `max_gap_resolution` where no
    //! more does, and goes finer first. When no grid that size reaches it (legs that all but touch), the
    //! gaps are left alone and the search is the usual one.
    std::function<double(double)> narrow_fraction;
    double max_narrow_fraction = 0.05;
    int max_gap_resolution = 12; //!< about 93 cm: the gaps may make a model that much larger, no more
    //! InitialModelOptions of every trial (resolution and b1 ignored; target_genus set to the
    //! surface's, so a grid counts when it or one of its nudges keeps the genus, as in a run).
    InitialModelOptions initial;
};

struct AutoResolution
{
    int resolution = 0;
    size_t balls = 0;        //!< of Z0 at that resolution
    size_t struts = 0;       //!< of Z0
    size_t target_nodes = 0; //!< the balls the annealer aims at
    double size_cm = 0.0;    //!< Z0's built longest side (z0_built_size_cm)
    long long genus = 0;     //!< of Z0
    long long surface_genus = 0;
    bool genus_kept = false;
    int preferred = 0; //!< the default grid
    //! The grid the search started from: the preferred one, or a finer one where parts that face each
    //! other across a gap narrower than the default's cell get a cell between them.
    int gap_resolution = 0;
    double narrow_at_preferred = 0.0; //!< the fraction of S's area facing a part closer than the default's cell
    //! Every grid from searched_from to searched_to was tried (and, but for the chosen one, missed the genus).
    int searched_from = 0;
    int searched_to = 0;
    std::vector<ResolutionTrial> trials; //!< in the order tried
    double seconds = 0.0;                //!< reported only; the choice never reads the clock
    //! One line for the user, the same in the CLI and on the page: the grid, Z0's balls, the
    //! target, the size, and why ("8 cells (210 balls, aiming at 378; about 63 cm): the default size").
    std::string message;
};

AutoResolution choose_resolution(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                                 const AutoResolutionOptions& options = {});

//! The balls the annealer is asked for from a Z0 of `z0_balls` balls: target_ratio times as many,
//! at most max_target, never fewer than Z0 has.
size_t target_balls(size_t z0_balls, const AutoResolutionOptions& options = {});

//! The longest side in cm of a built model spanning Z0's balls (one ball added): its B1 cells
//! times 74.86 mm.
double z0_built_size_cm(const ZomeModel& z0);

} // namespace zomeify
