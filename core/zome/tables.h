#pragma once
//! \file tables.h
//! The lookup tables of paper §5.1 (definitions in design.md §2), built once and immutable, so
//! any number of threads may read them:
//! - SPLITVECTOR(v): the ordered pairs (v*, v') of Zome vectors with v* + v' = v;
//! - MERGEVECTORS(v*, v'): the Zome vector v* + v', if there is one;
//! - CHANGEDIRECTIONS(v*, v'): the ordered pairs (w*, w') ≠ (v*, v') with w* + w' = v* + v',
//!   for keys with v* + v' ≠ 0 and v* ≠ v'.
//! All three are views of one structure: the 186² ordered pairs grouped by their exact sum.

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "core/zome/slots.h"

namespace zomeify {

//! An ordered pair of vector ids (0..185).
struct VecPair
{
    uint8_t first, second;
    friend bool operator==(const VecPair&, const VecPair&) = default;
};

class ZomeTables
{
public:
    //! The tables, built on first use (thread-safe) and shared; an allocation failure while
    //! building them ends the program (noexcept keeps JS trampolines off the hot path in wasm).
    static const ZomeTables& get() noexcept;
    //! A fresh, private copy (benchmarks measure construction with this).
    static std::unique_ptr<ZomeTables> build() { return std::unique_ptr<ZomeTables>(new ZomeTables()); }

    //! SPLITVECTOR(v) for a vector id v.
    std::span<const VecPair> split(int v) const { return group(split_group_[static_cast<size_t>(v)]); }
    //! MERGEVECTORS(a, b): the vector id of a + b, or -1.
    int merge(int a, int b) const { return merge_[key(a, b)]; }

    //! CHANGEDIRECTIONS(a, b): every pair of `group_of(a, b)` except (a, b) itself; empty when
    //! a + b = 0 or a = b. Visits them in a fixed order.
    template <class Fn>
    void for_each_change(int a, int b, Fn&& fn) const
    {
        if (a == b)
            return;
        const int g = pair_group_[key(a, b)];
        if (g == zero_group_)
            return;
        for (const VecPair& p : group(g))
            if (p.first != a || p.second != b)
                fn(p);
    }
    //! The number of CHANGEDIRECTIONS entries of (a, b).
    size_t change_count(int a, int b) const;

    //! Table sizes (the paper's figures) and memory held.
    size_t split_total() const;
    size_t merge_keys() const;
    size_t change_total() const;
    size_t memory_bytes() const;

private:
    ZomeTables();
    static size_t key(int a, int b) { return static_cast<size_t>(a) * kVectorCount + static_cast<size_t>(b); }
    std::span<const VecPair> group(int g) const
    {
        if (g < 0)
            return {};
        const auto begin = group_start_[static_cast<size_t>(g)], end = group_start_[static_cast<size_t>(g) + 1];
        return {pairs_.data() + begin, end - begin};
    }

    std::vector<VecPair> pairs_;        //!< all ordered pairs, grouped by sum
    std::vector<uint32_t> group_start_; //!< CSR offsets into pairs_
    std::vector<int32_t> pair_group_;   //!< group of each ordered pair (a·186 + b)
    std::vector<int16_t> merge_;        //!< MERGEVECTORS, −1 where a + b is no Zome vector
    std::vector<int32_t> split_group_;  //!< group whose sum is vector v, or −1
    int32_t zero_group_ = -1;           //!< the group of pairs summing to 0
};

} // namespace zomeify
