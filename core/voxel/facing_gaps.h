#pragma once
//! \file facing_gaps.h
//! Where parts of S nearly touch. Conservative cells merge two parts of S closer than about a cell, and
//! even when the genus survives (a knot's strands merged into one lump with one hole) the shape is lost.
//! This measures, at points spread evenly over S, the width of the gap in front of the surface: the
//! distance across to a part of S that faces back (a strand beside it, the far side of a narrow hole).

#include <vector>

#include "core/geom/closest_point.h"

namespace zomeify {

struct FacingGaps
{
    //! One entry per sample point: the width of the gap in front of it, in mesh units, or a negative
    //! value when no facing part lies within `max_width`.
    std::vector<double> widths;
    //! The fraction of S's area (the samples are area-weighted) facing a part closer than `width`.
    double fraction_narrower_than(double width) const;
};

//! `samples` points, area-weighted and deterministic, each looking along S's outward normal up to
//! `max_width`: the first point where another part of S, facing back (normals more than 120° apart),
//! is nearer than the point itself ends the look, and the width is the distance to that part.
FacingGaps facing_gaps(const SurfaceProjector& surface, double max_width, int samples = 4000);

} // namespace zomeify
