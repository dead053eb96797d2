#pragma once
//! \file run_settings.h
//! The one home of the run options every front end offers (issue 26): their defaults, bounds and
//! validation. The CLI (`zomeify run`), the wasm Session and the page's controls all read them
//! from here (the page through run_settings_schema_json() at start-up), so they cannot disagree.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/anneal/energy/energy_options.h"
#include "core/pipeline/pipeline.h"

namespace zomeify {

//! The time presets of the page (seconds); "standard" is the default budget everywhere.
struct TimePreset
{
    const char* name;
    double seconds;
};
const std::vector<TimePreset>& time_presets();

struct RunSettings
{
    int resolution = kAutoResolution; //!< cells along the longest side; 0 = automatic
    double seconds = 30.0;            //!< annealing time budget (the "standard" preset)
    //! > 0: stop after this many proposals instead of the time budget (one thread and a fixed seed:
    //! deterministic).
    uint64_t proposals = 0;
    long long target_nodes = 0; //!< N_target; 0 = the node count of Z0
    int threads = 0;            //!< annealing threads; 0 = automatic (each front end's rule)
    uint64_t seed = 1;
    bool initial_only = false; //!< stop after Z0
    //! > 0: the built longest side in cm (core/assembly/real_size.h) instead of the resolution; the
    //! front end that holds the mesh turns it into b1 (the CLI's --size-cm, the page's size field).
    double size_cm = 0.0;
    //! Continue from the model on screen instead of Z0 (the page's Improve, Fewer balls, More
    //! detail; the CLI's --from MODEL): the front end that holds the model sets PipelineOptions::from.
    bool continue_model = false;
    //! With continue_model, radius > 0: change only the model within `radius` of `near` (mesh
    //! units; the page's "Fix here", the CLI's --near/--radius).
    std::array<double, 3> near{};
    double radius = 0.0;
    EnergyOptions energy; //!< the energy's weights (energy_options.h)
    //! Auto: a mirror-symmetric model when the shape is symmetric (mirror_choice.h; JSON "mirror":
    //! "auto" | "off", the CLI's --mirror).
    MirrorMode mirror = MirrorMode::Off;

    //! Throws InvalidInputError with a one-line message naming the first option out of bounds.
    void check() const;
};

//! One numeric option: its JSON key (the page and the Session), its CLI flag, and its bounds.
struct OptionBounds
{
    const char* key;
    const char* flag;
    double min;
    double max;
    bool integer;
};
//! Every numeric RunSettings option, the weights under "weights.<name>".
const std::vector<OptionBounds>& run_option_bounds();
//! The bounds of one option by key ("resolution", "weights.dist", ...); throws std::out_of_range.
const OptionBounds& option_bounds(const std::string& key);

//! Reads a JSON object with any of the keys resolution, seconds, proposals, target_nodes, threads,
//! seed, initial_only, size_cm, continue, near [x, y, z], radius, mirror ("auto" | "off"), weights {dist, orient, fair,
//! complex, surface, fold}; missing keys keep their defaults. Throws InvalidInputError for a wrong type or a value out
//! of bounds.
RunSettings run_settings_from_json(const std::string& json);

//! The settings as that JSON (resolution 0 = automatic).
std::string run_settings_json(const RunSettings& settings = {});

//! What a front end needs to build its form: {"defaults": run_settings_json(), "bounds": {key:
//! {min, max, integer}}, "presets": {name: seconds}, "advice_max_resolution": N}.
std::string run_settings_schema_json();

//! The pipeline options these settings ask for (resolution 0 stays 0: run_pipeline chooses it).
PipelineOptions pipeline_options(const RunSettings& settings);

} // namespace zomeify
