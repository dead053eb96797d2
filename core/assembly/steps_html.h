#pragma once
//! \file steps_html.h
//! The build plan as one self-contained HTML page to print: a panel per step with a picture (inline
//! SVG drawn from the model: built parts grey, this step's struts in their colours, the rest faint)
//! and its parts. No scripts, no fonts, no requests.

#include <string>

#include "core/assembly/assembly_plan.h"

namespace zomeify {

//! `title` names the model (e.g. its file name); it is escaped.
std::string steps_html(const ZomeModel& model, const BuildPlan& plan, const std::string& title);

} // namespace zomeify
