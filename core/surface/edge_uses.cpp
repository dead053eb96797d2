#include "core/surface/edge_uses.h"

#include <algorithm>

namespace zomeify {

std::vector<EdgeUse> sorted_edge_uses(const std::vector<std::array<uint32_t, 3>>& triangles, size_t vertex_count)
{
    std::vector<uint32_t> start(vertex_count + 1, 0);
    for (const auto& t : triangles)
        for (int c = 0; c < 3; ++c)
            ++start[std::min(t[c], t[(c + 1) % 3]) + 1];
    for (size_t v = 0; v < vertex_count; ++v)
        start[v + 1] += start[v];
    std::vector<EdgeUse> uses(3 * triangles.size());
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (uint32_t f = 0; f < triangles.size(); ++f)
        for (uint8_t c = 0; c < 3; ++c)
        {
            const uint32_t a = triangles[f][c], b = triangles[f][(c + 1) % 3];
            uses[fill[std::min(a, b)]++] = {edge_key(a, b), f, c};
        }
    // Within a vertex's bucket the uses are in face order; a stable sort by key keeps it.
    const auto by_key = [](const EdgeUse& p, const EdgeUse& q) { return p.key < q.key; };
    for (size_t v = 0; v < vertex_count; ++v)
    {
        const auto first = uses.begin() + start[v], last = uses.begin() + start[v + 1];
        if (last - first <= 16)
        {
            for (auto i = first + (first != last); i < last; ++i)
                for (auto j = i; j > first && by_key(*j, *(j - 1)); --j)
                    std::iter_swap(j, j - 1);
        }
        else
            std::stable_sort(first, last, by_key);
    }
    return uses;
}

} // namespace zomeify
