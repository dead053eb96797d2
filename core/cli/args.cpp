#include "core/cli/args.h"

#include <cmath>
#include <cstdlib>

#include "core/base/errors.h"

namespace zomeify::cli {

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& valued,
           const std::set<std::string>& flags)
{
    for (size_t i = 0; i < argv.size(); ++i)
    {
        const std::string& a = argv[i];
        if (a.size() > 1 && a[0] == '-')
        {
            if (valued.count(a))
            {
                if (i + 1 >= argv.size())
                    throw InvalidInputError("option " + a + " needs a value");
                options_[a].push_back(argv[++i]);
            }
            else if (flags.count(a))
                options_[a].push_back("");
            else
                throw InvalidInputError("unknown option " + a);
        }
        else
            positional_.push_back(a);
    }
}

bool Args::has(const std::string& name) const { return options_.count(name) > 0; }

std::optional<std::string> Args::value(const std::string& name) const
{
    const auto it = options_.find(name);
    if (it == options_.end())
        return std::nullopt;
    if (it->second.size() > 1)
        throw InvalidInputError("option " + name + " given more than once");
    return it->second.front();
}

std::vector<std::string> Args::values(const std::string& name) const
{
    const auto it = options_.find(name);
    return it == options_.end() ? std::vector<std::string>{} : it->second;
}

double Args::number(const std::string& name, double fallback, double lo, double hi) const
{
    const auto v = value(name);
    if (!v)
        return fallback;
    char* end = nullptr;
    const double x = std::strtod(v->c_str(), &end);
    if (v->empty() || *end != '\0' || !std::isfinite(x) || x < lo || x > hi)
        throw InvalidInputError("option " + name + " wants a number in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "], got '" + *v + "'");
    return x;
}

long long Args::integer(const std::string& name, long long fallback, long long lo, long long hi) const
{
    const auto v = value(name);
    if (!v)
        return fallback;
    char* end = nullptr;
    const long long x = std::strtoll(v->c_str(), &end, 10);
    if (v->empty() || *end != '\0' || x < lo || x > hi)
        throw InvalidInputError("option " + name + " wants an integer in [" + std::to_string(lo) + ", " +
                                std::to_string(hi) + "], got '" + *v + "'");
    return x;
}

void Args::expect_positional(size_t n, const std::string& what) const
{
    if (positional_.size() != n)
        throw InvalidInputError("expected " + what);
}

} // namespace zomeify::cli
