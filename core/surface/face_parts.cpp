#include "core/surface/face_parts.h"

#include <algorithm>
#include <numeric>

namespace zomeify {

namespace {

constexpr uint32_t none = 0xFFFFFFFFu;

uint32_t find(std::vector<uint32_t>& parent, uint32_t x)
{
    while (parent[x] != x)
    {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

} // namespace

std::vector<uint32_t> face_parts(const std::vector<std::array<uint32_t, 3>>& triangles, size_t& count)
{
    struct Use
    {
        uint64_t key;
        uint32_t face;
    };
    std::vector<Use> uses;
    uses.reserve(3 * triangles.size());
    for (uint32_t f = 0; f < triangles.size(); ++f)
        for (int c = 0; c < 3; ++c)
        {
            const uint32_t p = triangles[f][c], q = triangles[f][(c + 1) % 3];
            uses.push_back({(uint64_t{std::min(p, q)} << 32) | std::max(p, q), f});
        }
    std::sort(uses.begin(), uses.end(), [](const Use& a, const Use& b) { return a.key < b.key; });
    std::vector<uint32_t> parent(triangles.size());
    std::iota(parent.begin(), parent.end(), uint32_t{0});
    for (size_t i = 1; i < uses.size(); ++i)
        if (uses[i].key == uses[i - 1].key)
        {
            const uint32_t a = find(parent, uses[i].face), b = find(parent, uses[i - 1].face);
            if (a != b)
                parent[std::max(a, b)] = std::min(a, b);
        }
    std::vector<uint32_t> part(triangles.size());
    std::vector<uint32_t> number(triangles.size(), none);
    count = 0;
    for (uint32_t f = 0; f < triangles.size(); ++f)
    {
        const uint32_t r = find(parent, f);
        if (number[r] == none)
            number[r] = static_cast<uint32_t>(count++);
        part[f] = number[r];
    }
    return part;
}

} // namespace zomeify
