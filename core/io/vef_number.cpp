#include "core/io/vef_number.h"

#include <charconv>
#include <numeric>
#include <vector>

#include "core/base/errors.h"

namespace zomeify {

namespace {

int64_t gcd64(int64_t x, int64_t y)
{
    // std::gcd of INT64_MIN is undefined; such values overflow anyway.
    if (x == INT64_MIN || y == INT64_MIN)
        detail::throw_overflow();
    return std::gcd(x, y);
}

GoldenFraction reduced(QPhi n, int64_t d)
{
    if (d < 0)
        n = -n, d = detail::checked_sub(0, d);
    const int64_t g = gcd64(gcd64(n.a, n.b), d);
    if (g > 1)
        n = QPhi{n.a / g, n.b / g}, d /= g;
    return {n, d};
}

[[noreturn]] void bad(std::string_view token, const std::string& what, const char* why)
{
    const std::string shown = token.size() > 40 ? std::string(token.substr(0, 40)) + "…" : std::string(token);
    throw InvalidInputError("not a valid VEF file: " + what + ": '" + shown + "' " + why);
}

// "p" or "p/q" with q != 0.
GoldenFraction parse_rational(std::string_view s, std::string_view token, const std::string& what)
{
    auto integer = [&](std::string_view t) {
        int64_t x = 0;
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
        if (!t.empty() && ec == std::errc::result_out_of_range)
            bad(token, what, "has a number too large for exact arithmetic here (at most 19 digits)");
        if (t.empty() || ec != std::errc() || end != t.data() + t.size())
            bad(token, what, "is not a number (integers, fractions p/q or (a,b) = a·φ + b)");
        return x;
    };
    const size_t slash = s.find('/');
    const int64_t p = integer(s.substr(0, slash));
    const int64_t q = slash == std::string_view::npos ? 1 : integer(s.substr(slash + 1));
    if (q == 0)
        bad(token, what, "divides by zero");
    return reduced(QPhi{p, 0}, q);
}

} // namespace

GoldenFraction GoldenFraction::operator+(const GoldenFraction& o) const
{
    using namespace detail;
    const int64_t g = gcd64(d, o.d);
    const int64_t l = checked_mul(d / g, o.d);
    const QPhi x = n * QPhi{o.d / g, 0}, y = o.n * QPhi{d / g, 0};
    return reduced(x + y, l);
}

GoldenFraction GoldenFraction::operator-(const GoldenFraction& o) const { return *this + GoldenFraction{-o.n, o.d}; }

GoldenFraction GoldenFraction::operator*(const GoldenFraction& o) const
{
    return reduced(n * o.n, detail::checked_mul(d, o.d));
}

GoldenFraction parse_vef_number(std::string_view token, bool rational_only, const std::string& what)
{
    if (token.size() < 2 || token.front() != '(' || token.back() != ')')
        return parse_rational(token, token, what);
    if (rational_only)
        bad(token, what, "is irrational, but the file declares 'field rational'");
    // Factors are written from the highest irrational down to the rational part.
    std::vector<std::string_view> factors;
    const std::string_view inner = token.substr(1, token.size() - 2);
    for (size_t start = 0;;)
    {
        const size_t comma = inner.find(',', start);
        factors.push_back(
            inner.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos)
            break;
        start = comma + 1;
        if (factors.size() > 8)
            bad(token, what, "has too many factors");
    }
    const size_t k = factors.size();
    GoldenFraction value = parse_rational(factors[k - 1], token, what);
    if (k >= 2)
    {
        const GoldenFraction phi_part = parse_rational(factors[k - 2], token, what);
        value = value + GoldenFraction{QPhi{0, phi_part.n.a}, phi_part.d};
    }
    for (size_t i = 0; i + 2 < k; ++i)
        if (!parse_rational(factors[i], token, what).n.is_zero())
            bad(token, what, "uses an irrational other than φ (not a Zome model)");
    return value;
}

} // namespace zomeify
