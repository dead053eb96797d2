#include "core/zome/qphi.h"

#include <ostream>

namespace zomeify {

namespace {
__extension__ typedef __int128 Int128; // products of two 62-bit numbers
}

void detail::throw_overflow()
{
    throw OverflowError("exact arithmetic overflow: coordinates are far outside any buildable model");
}

int QPhi::sign() const
{
    // a + bφ = ((2a + b) + b√5) / 2, so the sign is that of c + b√5 with c = 2a + b.
    // |a|, |b| < 2^61 keeps c² and 5b² inside 128 bits.
    constexpr int64_t kLimit = int64_t{1} << 61;
    if (a >= kLimit || a <= -kLimit || b >= kLimit || b <= -kLimit)
        detail::throw_overflow();
    const Int128 c = static_cast<Int128>(a) * 2 + b;
    const int sc = (c > 0) - (c < 0);
    const int sb = (b > 0) - (b < 0);
    if (sc == 0)
        return sb;
    if (sb == 0 || sc == sb)
        return sc;
    // Opposite signs: compare c² with 5b². Both fit in 128 bits for 64-bit a, b.
    const Int128 c2 = c * c;
    const Int128 b2 = static_cast<Int128>(b) * b * 5;
    if (c2 == b2)
        return 0; // impossible for integers unless both are 0 (√5 is irrational)
    return c2 > b2 ? sc : sb;
}

int compare(QPhi x, QPhi y) { return (x - y).sign(); }

QPhi phi_power(int n)
{
    QPhi r{1, 0};
    for (int i = 0; i < n; ++i)
        r = r.times_phi();
    for (int i = 0; i > n; --i)
        r = r.div_phi();
    return r;
}

std::ostream& operator<<(std::ostream& os, QPhi q) { return os << q.a << (q.b < 0 ? "" : "+") << q.b << "phi"; }

} // namespace zomeify
