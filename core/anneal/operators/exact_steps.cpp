#include "core/anneal/operators/exact_steps.h"

#include "core/zome/slots.h"
#include "core/zome/tables.h"

namespace zomeify::detail {

std::optional<ZVec> checked_add(const ZVec& a, const ZVec& b) noexcept
{
    ZVec r;
    for (size_t i = 0; i < 6; ++i)
        if (__builtin_add_overflow(a.c[i], b.c[i], &r.c[i]))
            return std::nullopt;
    return r;
}

int vector_between(const ZVec& from, const ZVec& to) noexcept
{
    ZVec d;
    for (size_t i = 0; i < 6; ++i)
        if (__builtin_sub_overflow(to.c[i], from.c[i], &d.c[i]))
            return -1;
    return vector_id_of(d);
}

std::optional<ZVec> split_position(const ZVec& start, int id, Rng& rng) noexcept
{
    if (id < 0)
        return std::nullopt;
    const auto pairs = ZomeTables::get().split(id);
    if (pairs.empty())
        return std::nullopt;
    return checked_add(start, zome_vector(pairs[rng.below(pairs.size())].first));
}

std::optional<ZVec> change_position(const ZVec& start, int a, int b, Rng& rng) noexcept
{
    if (a < 0 || b < 0)
        return std::nullopt;
    const ZomeTables& tables = ZomeTables::get();
    const size_t n = tables.change_count(a, b);
    if (n == 0)
        return std::nullopt;
    // The table is visited in a fixed order; pick the k-th entry.
    size_t k = rng.below(n);
    int first = -1;
    tables.for_each_change(a, b, [&](const VecPair& p) {
        if (k-- == 0)
            first = p.first;
    });
    return first < 0 ? std::nullopt : checked_add(start, zome_vector(first));
}

} // namespace zomeify::detail
