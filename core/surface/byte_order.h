#pragma once
//! \file byte_order.h
//! Reading little- and big-endian numbers from unaligned bytes, independent of the host's order.

#include <cstdint>
#include <cstring>

namespace zomeify::detail {

//! The `n` (1, 2, 4 or 8) bytes at `p` as an unsigned integer in the given byte order.
inline uint64_t load_uint(const uint8_t* p, int n, bool big_endian)
{
    uint64_t v = 0;
    for (int i = 0; i < n; ++i)
        v |= static_cast<uint64_t>(p[big_endian ? n - 1 - i : i]) << (8 * i);
    return v;
}

inline uint32_t load_u32_le(const uint8_t* p) { return static_cast<uint32_t>(load_uint(p, 4, false)); }

//! The bits of `u` as a float (memcpy rather than std::bit_cast, which not every toolchain we build with has).
inline float float_from_bits(uint32_t u)
{
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
}

inline float load_f32(const uint8_t* p, bool big_endian)
{
    return float_from_bits(static_cast<uint32_t>(load_uint(p, 4, big_endian)));
}

inline double load_f64(const uint8_t* p, bool big_endian)
{
    const uint64_t u = load_uint(p, 8, big_endian);
    double d;
    std::memcpy(&d, &u, sizeof d);
    return d;
}

} // namespace zomeify::detail
