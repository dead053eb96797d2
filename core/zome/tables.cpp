#include "core/zome/tables.h"

#include <unordered_map>

namespace zomeify {

const ZomeTables& ZomeTables::get() noexcept
{
    static const ZomeTables tables;
    return tables;
}

ZomeTables::ZomeTables()
{
    constexpr size_t kPairs = static_cast<size_t>(kVectorCount) * kVectorCount;
    // Group every ordered pair by its exact sum.
    std::unordered_map<ZVec, int32_t, ZVecHash> group_of_sum;
    std::vector<ZVec> sums;
    pair_group_.resize(kPairs);
    std::vector<uint32_t> group_size;
    for (int a = 0; a < kVectorCount; ++a)
        for (int b = 0; b < kVectorCount; ++b)
        {
            const ZVec s = zome_vector(a) + zome_vector(b);
            auto [it, inserted] = group_of_sum.try_emplace(s, static_cast<int32_t>(sums.size()));
            if (inserted)
            {
                sums.push_back(s);
                group_size.push_back(0);
            }
            pair_group_[key(a, b)] = it->second;
            ++group_size[static_cast<size_t>(it->second)];
        }
    // CSR layout, pairs in (a, b) order inside each group.
    group_start_.assign(sums.size() + 1, 0);
    for (size_t g = 0; g < sums.size(); ++g)
        group_start_[g + 1] = group_start_[g] + group_size[g];
    pairs_.resize(kPairs);
    std::vector<uint32_t> fill(group_start_.begin(), group_start_.end() - 1);
    for (int a = 0; a < kVectorCount; ++a)
        for (int b = 0; b < kVectorCount; ++b)
            pairs_[fill[static_cast<size_t>(pair_group_[key(a, b)])]++] =
                VecPair{static_cast<uint8_t>(a), static_cast<uint8_t>(b)};

    // SPLITVECTOR and MERGEVECTORS: groups whose sum is itself a Zome vector.
    split_group_.assign(kVectorCount, -1);
    merge_.assign(kPairs, -1);
    for (size_t g = 0; g < sums.size(); ++g)
    {
        if (sums[g].is_zero())
            zero_group_ = static_cast<int32_t>(g);
        const int v = vector_id_of(sums[g]);
        if (v < 0)
            continue;
        split_group_[static_cast<size_t>(v)] = static_cast<int32_t>(g);
        for (const VecPair& p : group(static_cast<int>(g)))
            merge_[key(p.first, p.second)] = static_cast<int16_t>(v);
    }
}

size_t ZomeTables::change_count(int a, int b) const
{
    if (a == b)
        return 0;
    const int g = pair_group_[key(a, b)];
    return g == zero_group_ ? 0 : group(g).size() - 1;
}

size_t ZomeTables::split_total() const
{
    size_t n = 0;
    for (int v = 0; v < kVectorCount; ++v)
        n += split(v).size();
    return n;
}

size_t ZomeTables::merge_keys() const
{
    size_t n = 0;
    for (int16_t m : merge_)
        n += (m >= 0);
    return n;
}

size_t ZomeTables::change_total() const
{
    size_t n = 0;
    for (int a = 0; a < kVectorCount; ++a)
        for (int b = 0; b < kVectorCount; ++b)
            n += change_count(a, b);
    return n;
}

size_t ZomeTables::memory_bytes() const
{
    return sizeof(*this) + pairs_.capacity() * sizeof(VecPair) + group_start_.capacity() * sizeof(uint32_t) +
           pair_group_.capacity() * sizeof(int32_t) + merge_.capacity() * sizeof(int16_t) +
           split_group_.capacity() * sizeof(int32_t);
}

} // namespace zomeify
