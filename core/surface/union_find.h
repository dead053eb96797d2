#pragma once
//! \file union_find.h
//! Disjoint sets over 0..n−1 (path halving; the smaller index is the root, so results do not
//! depend on the order of unions): fans of faces, parts, groups of overlapping parts.

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace zomeify {

class UnionFind
{
public:
    explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), uint32_t{0}); }
    uint32_t find(uint32_t x)
    {
        while (parent_[x] != x)
        {
            parent_[x] = parent_[parent_[x]]; // path halving keeps the trees flat
            x = parent_[x];
        }
        return x;
    }
    void unite(uint32_t a, uint32_t b)
    {
        a = find(a);
        b = find(b);
        if (a != b)
            parent_[std::max(a, b)] = std::min(a, b);
    }

private:
    std::vector<uint32_t> parent_;
};

} // namespace zomeify
