#pragma once
//! \file hash.h
//! A 64-bit finaliser (splitmix64's) that spreads every input bit over the output, for hash
//! tables keyed by small or structured integers.

#include <cstdint>

namespace zomeify {

constexpr uint64_t mix64(uint64_t x) noexcept
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return x;
}

} // namespace zomeify
