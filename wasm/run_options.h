#pragma once
//! \file run_options.h
//! What the page asks a run to do: the core's RunSettings (core/pipeline/run_settings.h, the one
//! home of every option's default and bounds), parsed from the JSON the worker sends.

#include <string>

#include "core/pipeline/run_settings.h"

namespace zomeify::web {

using RunOptions = RunSettings;

//! run_settings_from_json(): missing keys keep their defaults; InvalidInputError for a value of the
//! wrong type or out of bounds.
inline RunOptions parse_run_options(const std::string& json) { return run_settings_from_json(json); }

//! The largest number of annealing threads this build can start without deadlocking
//! (PTHREAD_POOL_SIZE minus the run's own thread; 1 in the single-threaded build).
int max_run_threads();

} // namespace zomeify::web
