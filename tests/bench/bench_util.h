#pragma once
//! \file bench_util.h
//! Shared helpers of the benchmark executables: medians of repeated timings, peak memory, and
//! the platform name, so each benchmark prints one comparable JSON object.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/base/stopwatch.h"

#if defined(__EMSCRIPTEN__)
#include <malloc.h>
#else
#include <sys/resource.h>
#endif

namespace zomeify::bench {

//! Median wall time in seconds of `runs` calls of `fn`.
inline double median_seconds(int runs, const std::function<void()>& fn)
{
    std::vector<double> t;
    for (int i = 0; i < runs; ++i)
    {
        Stopwatch sw;
        fn();
        t.push_back(sw.seconds());
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

//! Peak resident memory of the process in MiB natively; under Emscripten the heap bytes in use
//! now (dlmalloc's mallinfo), since the wasm memory itself is reserved up front.
inline double peak_memory_mib()
{
#if defined(__EMSCRIPTEN__)
    return static_cast<double>(mallinfo().uordblks) / (1024.0 * 1024.0);
#else
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    return static_cast<double>(ru.ru_maxrss) / 1024.0;
#endif
}

inline std::string platform()
{
#if defined(__EMSCRIPTEN__)
    return "wasm";
#else
    return "native";
#endif
}

//! A positional command-line number that must be positive and finite ("what" names it in the
//! error); the CLI's Args::number does the same for named options.
inline double positive_argument(const char* text, const char* what)
{
    char* end = nullptr;
    const double x = std::strtod(text, &end);
    if (end == text || *end != '\0' || !std::isfinite(x) || !(x > 0.0))
    {
        throw std::invalid_argument(std::string(what) + " must be a positive number, not '" + text + "'");
    }
    return x;
}

//! Runs a benchmark's body and turns an exception (a missing mesh, a bad argument) into one line
//! on stderr and exit code 2, instead of std::terminate.
inline int guarded_main(int argc, char** argv, int (*body)(int, char**))
{
    try
    {
        return body(argc, argv);
    }
    catch (const std::exception& e)
    {
        std::cerr << argv[0] << ": error: " << e.what() << "\n";
        return 2;
    }
}

} // namespace zomeify::bench
