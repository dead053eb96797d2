#pragma once
//! \file fuzz_target.h
//! One source per fuzz target, built two ways:
//!   - with libFuzzer (ZOME_FUZZ_LIBFUZZER, build/fuzz): ZOME_FUZZ_TARGET defines LLVMFuzzerTestOneInput;
//!   - into `fuzz_replay` (every normal build): it registers the body under its name, and the replay
//!     program runs the committed regression corpus through it (a ctest test).
//! A body returns 0 for every input; anything else it finds (a crash, a sanitizer report, a broken
//! invariant) is a finding. ZOME_FUZZ_CHECK aborts with a message, so both builds report it.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace zomeify::fuzz {

using TargetFn = int (*)(const uint8_t* data, size_t size);

//! Adds a target to the replay program's table; returns true so it can initialise a static.
bool register_target(const char* name, TargetFn fn);

} // namespace zomeify::fuzz

#ifdef ZOME_FUZZ_LIBFUZZER
#define ZOME_FUZZ_TARGET(name) extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
#else
#define ZOME_FUZZ_TARGET(name)                                                                                         \
    static int fuzz_body_##name(const uint8_t* data, size_t size);                                                     \
    [[maybe_unused]] static const bool fuzz_registered_##name =                                                        \
        zomeify::fuzz::register_target(#name, fuzz_body_##name);                                                       \
    static int fuzz_body_##name(const uint8_t* data, size_t size)
#endif

//! An invariant the code under test promises; a violation is a finding.
#define ZOME_FUZZ_CHECK(cond, what)                                                                                    \
    do                                                                                                                 \
    {                                                                                                                  \
        if (!(cond))                                                                                                   \
        {                                                                                                              \
            std::fprintf(stderr, "fuzz invariant broken: %s (%s)\n", what, #cond);                                     \
            std::abort();                                                                                              \
        }                                                                                                              \
    } while (false)
