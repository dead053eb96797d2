#pragma once
//! \file run_progress.h
//! What a run reports while it works, and how the page stops it. The run's thread writes, the
//! worker's thread reads; one small mutex, touched a few times a second.

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>

#include "wasm/run_options.h"

namespace zomeify::web {

enum class RunState : uint8_t
{
    Idle,
    Initial,   //!< building Z0
    Annealing, //!< the annealer works
    Done,      //!< finished (time budget reached)
    Cancelled, //!< stopped by the page; the best model is kept
    Failed,    //!< error holds the one-line message
};

struct RunProgress
{
    RunState state = RunState::Idle;
    double seconds = 0.0;        //!< wall time since the run started
    double budget_seconds = 0.0; //!< annealing budget (0 with a proposal budget)
    double fraction = 0.0;       //!< of the budget used, in [0, 1]
    double temperature = 0.0;
    double energy = 0.0;      //!< current energy
    double best_energy = 0.0; //!< lowest energy seen
    uint64_t proposals = 0;
    uint64_t commits = 0;
    size_t nodes = 0;
    size_t struts = 0;
    int threads = 1;
    bool annealer = false; //!< false: Z0 only (initial_only)
    bool valid = false;    //!< at the end: the model passed validate()
    long long genus = 0;   //!< at the end: genus of the model
    long long surface_genus = 0;
    //! Fidelity of the model so far (core/score, fewer samples during the run, all at the end):
    //! the largest gap and the typical (RMS) distance both ways, in mm at real size; 0 = not yet.
    double gap_mm = 0.0;
    double rms_mm = 0.0;
    std::string note; //!< e.g. the advisor's hint
    std::string error;

    bool finished() const
    {
        return state == RunState::Done || state == RunState::Cancelled || state == RunState::Failed;
    }
    //! One JSON object (keys as the fields above; state as a word).
    std::string json() const;
};

//! Shared between the worker thread and the run thread.
class RunControl
{
public:
    void request_cancel() { cancel_.store(true); }
    bool cancel_requested() const { return cancel_.load(); }
    const std::atomic<bool>& cancel_flag() const { return cancel_; }
    std::atomic<bool>& cancel_flag() { return cancel_; }

    RunProgress get() const
    {
        std::lock_guard lock(mutex_);
        return progress_;
    }
    template <class F>
    void update(F&& change)
    {
        {
            std::lock_guard lock(mutex_);
            change(progress_);
        }
        tick();
    }

    //! Single-threaded build: the run calls back into the worker's JS (which cannot receive
    //! messages meanwhile) every `interval` seconds; a true answer asks the run to stop.
    void set_reporter(std::function<bool(const RunProgress&)> reporter, double interval)
    {
        reporter_ = std::move(reporter);
        interval_ = interval;
    }
    //! Called often by the run (on its own thread); reports when a reporter is set and due.
    void tick();

private:
    std::atomic<bool> cancel_{false};
    mutable std::mutex mutex_;
    RunProgress progress_;
    std::function<bool(const RunProgress&)> reporter_;
    double interval_ = 0.25;
    double last_report_ = -1.0;
};

} // namespace zomeify::web
