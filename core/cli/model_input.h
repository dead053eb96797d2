#pragma once
//! \file model_input.h
//! Reading a model file for a command: the model as it is, with a warning on stderr when its parts
//! could not be built side by side (design.md §3.8). The command still does its job.

#include <string>

#include "core/zome/model.h"

namespace zomeify::cli {

//! read_model_file(path), its notes as "note: PATH: …" on stderr (vef.h), then "warning: PATH: N
//! clashes: …" if it has clashes.
ZomeModel read_model_warning_of_clashes(const std::string& path);

//! The same warning for a model from elsewhere (a share link), named `source`.
void warn_of_clashes(const ZomeModel& model, const std::string& source);

} // namespace zomeify::cli
