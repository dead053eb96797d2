#pragma once
//! \file random.h
//! Rng: the annealer's random numbers. Our own generator (xoshiro256**, seeded via splitmix64) and
//! our own integer → real mapping, because std:: distributions differ between libstdc++ (native)
//! and libc++ (wasm), and one thread with a fixed seed must give a bit-identical model on both.

#include <cstdint>

namespace zomeify {

class Rng
{
public:
    explicit Rng(uint64_t seed = 0) noexcept
    {
        uint64_t x = seed;
        for (uint64_t& s : state_)
            s = splitmix64(x);
    }
    //! 64 uniform bits.
    uint64_t next() noexcept
    {
        const uint64_t result = rotl(state_[1] * 5, 7) * 9;
        const uint64_t t = state_[1] << 17;
        state_[2] ^= state_[0];
        state_[3] ^= state_[1];
        state_[1] ^= state_[2];
        state_[0] ^= state_[3];
        state_[2] ^= t;
        state_[3] = rotl(state_[3], 45);
        return result;
    }
    //! Uniform in [0, n) for n ≥ 1 (multiply-shift; bias < n / 2^64, irrelevant here).
    uint64_t below(uint64_t n) noexcept
    {
        __extension__ using Wide = unsigned __int128; // GCC/Clang (and Emscripten) extension
        return static_cast<uint64_t>((static_cast<Wide>(next()) * n) >> 64);
    }
    //! Uniform in [0, 1) with 53 random bits.
    double uniform01() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    //! An independent stream for thread `index` (deterministic in the seed and the index).
    static Rng for_stream(uint64_t seed, uint64_t index) noexcept
    {
        return Rng(seed ^ (0x9E3779B97F4A7C15ULL * (index + 1)));
    }

private:
    static uint64_t rotl(uint64_t x, int k) noexcept { return (x << k) | (x >> (64 - k)); }
    static uint64_t splitmix64(uint64_t& x) noexcept
    {
        uint64_t z = (x += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }
    uint64_t state_[4];
};

} // namespace zomeify
