#include "core/zome/zvec.h"

#include "core/base/hash.h"

#include <limits>
#include <ostream>

namespace zomeify {

namespace {
int32_t narrow(int64_t x)
{
    if (x > std::numeric_limits<int32_t>::max() || x < std::numeric_limits<int32_t>::min())
        detail::throw_overflow();
    return static_cast<int32_t>(x);
}
} // namespace

ZVec ZVec::from_twice(QPhi x2, QPhi y2, QPhi z2)
{
    return ZVec{{narrow(x2.b), narrow(x2.a), narrow(y2.b), narrow(y2.a), narrow(z2.b), narrow(z2.a)}};
}

ZVec ZVec::operator+(const ZVec& o) const
{
    ZVec r;
    for (int i = 0; i < 6; ++i)
        if (__builtin_add_overflow(c[i], o.c[i], &r.c[i]))
            detail::throw_overflow();
    return r;
}

ZVec ZVec::operator-(const ZVec& o) const
{
    ZVec r;
    for (int i = 0; i < 6; ++i)
        if (__builtin_sub_overflow(c[i], o.c[i], &r.c[i]))
            detail::throw_overflow();
    return r;
}

ZVec ZVec::operator-() const { return ZVec{} - *this; }

ZVec ZVec::times_phi() const { return from_twice(twice(0).times_phi(), twice(1).times_phi(), twice(2).times_phi()); }

ZVec ZVec::div_phi() const { return from_twice(twice(0).div_phi(), twice(1).div_phi(), twice(2).div_phi()); }

QPhi dot4(const ZVec& u, const ZVec& v)
{
    return u.twice(0) * v.twice(0) + u.twice(1) * v.twice(1) + u.twice(2) * v.twice(2);
}

size_t ZVecHash::operator()(const ZVec& v) const noexcept
{
    // Three 64-bit words of packed coordinates, each mixed with a splitmix64 finaliser.
    uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (int i = 0; i < 6; i += 2)
    {
        const uint64_t w =
            (static_cast<uint64_t>(static_cast<uint32_t>(v.c[i])) << 32) | static_cast<uint32_t>(v.c[i + 1]);
        h = mix64(h ^ w) + 0x9e3779b97f4a7c15ULL;
    }
    return static_cast<size_t>(h);
}

std::ostream& operator<<(std::ostream& os, const ZVec& v)
{
    os << '[';
    for (int i = 0; i < 6; ++i)
        os << (i ? "," : "") << v.c[i];
    return os << ']';
}

} // namespace zomeify
