#pragma once
//! \file output_options.h
//! The writers' options every command that writes models shares: `--obj-units mm|m` and
//! `--no-faces` (VEF without panels).

#include "core/cli/args.h"
#include "core/io/model_io.h"

namespace zomeify::cli {

inline constexpr const char* kObjUnitsOption = "--obj-units";
inline constexpr const char* kNoFacesFlag = "--no-faces";

//! The options from parsed arguments (InvalidInputError for a bad unit).
WriteOptions write_options(const Args& args);

} // namespace zomeify::cli
