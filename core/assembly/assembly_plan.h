#pragma once
//! \file assembly_plan.h
//! The order in which a person builds a model at a table: an upright pose, the lowest ball first,
//! then steps of a few parts that always attach to what stands, grow upward and close triangles
//! early (a triangulated shell stands on its own, a ring of quads folds). Deterministic.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/zome/lattice_mirror.h"
#include "core/zome/model.h"

namespace zomeify {

//! Which model axis points up: axis 0..2 (x, y, z) and its sign.
struct UpAxis
{
    int axis = 1;
    int sign = 1;
};

//! "y" (default), "-y", "x", "+z", ...; throws InvalidInputError otherwise.
UpAxis parse_up_axis(const std::string& text);

struct BuildStep
{
    std::vector<uint32_t> balls;  //!< balls this step adds, in the order to place them
    std::vector<uint32_t> struts; //!< indices into model.struts this step adds
    std::vector<uint32_t> attach; //!< balls built before this step that the new struts hold (sorted)
};

//! The figures of issue 24 for one sequence.
struct PlanFigures
{
    size_t steps = 0;
    double max_overhang_b0 = 0; //!< largest height of a new ball above its highest supporting ball below it
    double two_strut_share = 0; //!< share of steps after which every new ball has >= 2 struts
    size_t max_dangling = 0;    //!< most balls held by a single strut after any step (they swing)
};

struct BuildPlan
{
    UpAxis up;
    //! Set when the steps build both halves alike: every step is its own mirror image about this plane.
    std::optional<LatticeMirror> mirror;
    std::vector<BuildStep> steps;
    PlanFigures figures;
};

struct PlanOptions
{
    UpAxis up;
    int min_parts = 6;  //!< a step closes once it has at least this many parts...
    int max_parts = 12; //!< ...and before a ball would take it past this many
    //! Build both halves alike (issue 41): each ball goes into its step with its mirror image, so that
    //! every step is symmetric. A plane across an axis other than up that the model maps onto exactly
    //! (building_mirror); plan_assembly throws InvalidInputError for any other.
    std::optional<LatticeMirror> mirror;
};

//! The plane to build a model's halves alike about: one across an axis other than `up` that the model
//! maps onto exactly (its own plane, model_mirror, first); nothing for an asymmetric model.
std::optional<LatticeMirror> building_mirror(const ZomeModel& model, UpAxis up);

//! The planner's order. Throws InvalidInputError for an empty or disconnected model or bad indices.
BuildPlan plan_assembly(const ZomeModel& model, const PlanOptions& options = {});

//! The naive order to compare with: breadth-first from the lowest ball, cut into steps the same way.
BuildPlan plan_breadth_first(const ZomeModel& model, const PlanOptions& options = {});

//! Height of every ball along the up axis, in b0.
std::vector<double> ball_heights(const ZomeModel& model, UpAxis up);

//! The figures of a plan (the planners fill them in; exposed for tests and other orders).
PlanFigures plan_figures(const ZomeModel& model, const std::vector<BuildStep>& steps, UpAxis up);

//! Empty when every ball and strut is in exactly one step and every step attaches to earlier
//! ones (the first holds one piece), and with plan.mirror every step is its own mirror image;
//! otherwise a one-line description of the first fault.
std::string check_plan(const ZomeModel& model, const BuildPlan& plan);

} // namespace zomeify
