#include "wasm/run_options.h"

#include <nlohmann/json.hpp>

#include "core/base/errors.h"

namespace zomeify::web
{

namespace
{

double number_in(const nlohmann::json &j, const char *key, double fallback, double lo, double hi)
{
    if (!j.contains(key))
        return fallback;
    const nlohmann::json &v = j.at(key);
    if (!v.is_number())
        throw InvalidInputError(std::string("run option '") + key + "' must be a number");
    const double x = v.get<double>();
    if (!(x >= lo && x <= hi))
        throw InvalidInputError(std::string("run option '") + key + "' must be between " + std::to_string(lo) +
                                " and " + std::to_string(hi));
    return x;
}

} // namespace

RunOptions parse_run_options(const std::string &json)
{
    const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        throw InvalidInputError("run options must be a JSON object");
    RunOptions o;
    o.resolution = static_cast<int>(number_in(j, "resolution", o.resolution, 2, 256));
    o.seconds = number_in(j, "seconds", o.seconds, 0, 24 * 3600);
    o.proposals = static_cast<uint64_t>(number_in(j, "proposals", 0, 0, 1e12));
    if (j.contains("initial_only"))
    {
        if (!j.at("initial_only").is_boolean())
            throw InvalidInputError("run option 'initial_only' must be true or false");
        o.initial_only = j.at("initial_only").get<bool>();
    }
    o.target_nodes = static_cast<long long>(number_in(j, "target_nodes", 0, 0, 2'000'000));
    o.threads = static_cast<int>(number_in(j, "threads", o.threads, 1, 64));
    o.seed = static_cast<uint64_t>(number_in(j, "seed", 1, 0, 9007199254740991.0));
    if (j.contains("weights"))
    {
        const nlohmann::json &w = j.at("weights");
        if (!w.is_object())
            throw InvalidInputError("run option 'weights' must be an object");
        EnergyOptions& e = o.energy;
        e.w_distance = number_in(w, "dist", e.w_distance, 0, 1e6);
        e.w_orientation = number_in(w, "orient", e.w_orientation, 0, 1e6);
        e.w_fairing = number_in(w, "fair", e.w_fairing, 0, 1e6);
        e.w_complexity = number_in(w, "complex", e.w_complexity, 0, 1e6);
        e.w_surface = number_in(w, "surface", e.w_surface, 0, 1e6);
        e.w_fold = number_in(w, "fold", e.w_fold, 0, 1e6);
    }
    return o;
}

std::string default_run_options_json()
{
    const RunOptions o;
    const EnergyOptions& e = o.energy;
    nlohmann::json j = {{"resolution", o.resolution},
                        {"seconds", o.seconds},
                        {"threads", o.threads},
                        {"seed", o.seed},
                        {"weights",
                         {{"dist", e.w_distance},
                          {"orient", e.w_orientation},
                          {"fair", e.w_fairing},
                          {"complex", e.w_complexity},
                          {"surface", e.w_surface},
                          {"fold", e.w_fold}}}};
    return j.dump();
}

int max_run_threads()
{
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    return 1;
#elif defined(ZOME_WEB_POOL_SIZE)
    // One pool worker runs the pipeline and is itself annealing thread 0; one more stays spare.
    return ZOME_WEB_POOL_SIZE - 1;
#else
    return 4;
#endif
}

} // namespace zomeify::web
