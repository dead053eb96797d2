#include "core/surface/face_parts.h"

#include <algorithm>
#include <numeric>

#include "core/surface/edge_uses.h"

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
    size_t vertex_count = 0;
    for (const auto& t : triangles)
        vertex_count = std::max<size_t>(vertex_count, std::max({t[0], t[1], t[2]}) + size_t{1});
    const std::vector<EdgeUse> uses = sorted_edge_uses(triangles, vertex_count);
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
