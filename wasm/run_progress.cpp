#include "wasm/run_progress.h"

#include <chrono>

#include <nlohmann/json.hpp>

namespace zomeify::web {

namespace {

const char* state_name(RunState s)
{
    switch (s)
    {
    case RunState::Idle:
        return "idle";
    case RunState::Initial:
        return "initial";
    case RunState::Annealing:
        return "annealing";
    case RunState::Done:
        return "done";
    case RunState::Cancelled:
        return "cancelled";
    case RunState::Failed:
        return "failed";
    }
    return "idle";
}

} // namespace

std::string RunProgress::json() const
{
    nlohmann::json j;
    j["state"] = state_name(state);
    j["seconds"] = seconds;
    j["budget_seconds"] = budget_seconds;
    j["fraction"] = fraction;
    j["temperature"] = temperature;
    j["energy"] = energy;
    j["best_energy"] = best_energy;
    j["proposals"] = proposals;
    j["commits"] = commits;
    j["nodes"] = nodes;
    j["struts"] = struts;
    j["threads"] = threads;
    j["annealer"] = annealer;
    j["valid"] = valid;
    j["genus"] = genus;
    j["surface_genus"] = surface_genus;
    j["gap_mm"] = gap_mm;
    j["rms_mm"] = rms_mm;
    j["note"] = note;
    j["error"] = error;
    return j.dump();
}

void RunControl::tick()
{
    if (!reporter_)
        return;
    using Clock = std::chrono::steady_clock;
    const double now = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
    if (last_report_ >= 0.0 && now - last_report_ < interval_)
        return;
    last_report_ = now;
    if (reporter_(get()))
        request_cancel();
}

} // namespace zomeify::web
