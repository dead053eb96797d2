#pragma once
//! \file stopwatch.h
//! Wall-clock timing for the CLI and benchmarks.

#include <chrono>

namespace zomeify {

class Stopwatch
{
public:
    Stopwatch() : start_(Clock::now()) {}
    void restart() { start_ = Clock::now(); }
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_;
};

} // namespace zomeify
