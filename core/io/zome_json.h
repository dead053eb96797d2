#pragma once
//! \file zome_json.h
//! The project's model format `.zome.json` (design.md §4):
//! {"format":"zomeify-model","version":1,"nodes":[[a0..a5],...],"struts":[[i,j],...],
//!  "faces":[[i,j,k(,l)],...],"transform":{"scale":s,"translation":[x,y,z]},"stats":{...}}.
//! Reading validates everything (check_model) and answers bad input with InvalidInputError.

#include <string>
#include <string_view>

#include "core/zome/model.h"

namespace zomeify {

std::string write_zome_json(const ZomeModel& model);

ZomeModel read_zome_json(std::string_view text);

} // namespace zomeify
