#pragma once
//! \file plan_report.h
//! A build plan as the CLI and the page show it: per step the parts by part code, the balls they
//! attach to, and the figures (JSON and a text table).

#include <array>
#include <string>

#include "core/assembly/assembly_plan.h"
#include "core/zome/slots.h"

namespace zomeify {

//! The strut kind of each strut of the model; throws InvalidInputError for a non-Zome strut.
std::vector<StrutKind> strut_kinds(const ZomeModel& model);

//! Struts of a step per kind (B0..R2).
std::array<size_t, kStrutKindCount> step_strut_counts(const std::vector<StrutKind>& kinds, const BuildStep& step);

//! {"up":"y",["mirror":{"axis":"z","coordinate_b0":0},]"nodes":[[6
//! ints]...],"steps":[{"balls":[..],"struts":[[i,j]..],"attach":[..],
//!  "parts":{"PZB-BAL-W":n,"PST-B1-BLU":n,..}}..],"figures":{..},"naive":{..}}.
//! `naive` holds the breadth-first order's figures for comparison.
std::string plan_json(const ZomeModel& model, const BuildPlan& plan, const PlanFigures& naive);

//! One line a step ("step 3: 2 balls, 5 struts (B1 x2, Y0 x3) on balls 4, 7") and the figures.
std::string plan_text(const ZomeModel& model, const BuildPlan& plan, const PlanFigures& naive);

//! "Both halves are built alike: each step adds its parts with their mirror images about the plane
//! across the z axis." for a plan with a mirror; empty otherwise.
std::string halves_alike_text(const BuildPlan& plan);

//! "y", "-z", ...
std::string up_axis_name(UpAxis up);

} // namespace zomeify
