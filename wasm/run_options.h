#pragma once
//! \file run_options.h
//! What the page asks a run to do, parsed from the JSON the worker sends (web/README.md, "run").

#include <cstdint>
#include <string>

#include "core/anneal/energy_options.h"

namespace zomeify::web
{

struct RunOptions
{
    int resolution = 12;   //!< cells along the longest side for Z0
    double seconds = 10.0; //!< annealing time budget
    //! > 0: a proposal budget instead of the time budget (with one thread and a fixed seed the
    //! run is then deterministic, bit-identical to the native CLI).
    uint64_t proposals = 0;
    bool initial_only = false;  //!< stop after Z0
    long long target_nodes = 0; //!< N_target; 0 = the node count of Z0
    int threads = 1;            //!< annealing threads (clamped to what the build offers)
    uint64_t seed = 1;
    //! The energy's weights, the core's defaults unless the page sends others (it folds them away
    //! under "advanced" and reads their defaults from default_run_options_json()).
    EnergyOptions energy;
};

//! Parses a JSON object with any of the keys resolution, seconds, proposals, initial_only,
//! target_nodes, threads, seed,
//! weights {dist, orient, fair, complex, surface, fold}; missing keys keep their defaults. Throws
//! InvalidInputError with a one-line message for a value of the wrong type or out of range.
RunOptions parse_run_options(const std::string &json);

//! RunOptions{} as the JSON parse_run_options() reads (the page's form starts from it).
std::string default_run_options_json();

//! The largest number of annealing threads this build can start without deadlocking
//! (PTHREAD_POOL_SIZE minus the run's own thread; 1 in the single-threaded build).
int max_run_threads();

} // namespace zomeify::web
