#include "core/surface/face_parts.h"

#include <algorithm>

#include "core/surface/edge_uses.h"
#include "core/surface/union_find.h"

namespace zomeify {

namespace {

constexpr uint32_t none = 0xFFFFFFFFu;

} // namespace

std::vector<uint32_t> face_parts(const std::vector<std::array<uint32_t, 3>>& triangles, size_t& count)
{
    size_t vertex_count = 0;
    for (const auto& t : triangles)
        vertex_count = std::max<size_t>(vertex_count, std::max({t[0], t[1], t[2]}) + size_t{1});
    const std::vector<EdgeUse> uses = sorted_edge_uses(triangles, vertex_count);
    UnionFind parts(triangles.size());
    for (size_t i = 1; i < uses.size(); ++i)
        if (uses[i].key == uses[i - 1].key)
        {
            parts.unite(uses[i].face, uses[i - 1].face);
        }
    std::vector<uint32_t> part(triangles.size());
    std::vector<uint32_t> number(triangles.size(), none);
    count = 0;
    for (uint32_t f = 0; f < triangles.size(); ++f)
    {
        const uint32_t r = parts.find(f);
        if (number[r] == none)
            number[r] = static_cast<uint32_t>(count++);
        part[f] = number[r];
    }
    return part;
}

void drop_unused_vertices(TriangleMesh& mesh, std::vector<uint32_t>* per_vertex)
{
    std::vector<uint32_t> index(mesh.positions.size(), none);
    for (const auto& t : mesh.triangles)
        for (const uint32_t v : t)
            index[v] = 0;
    uint32_t used = 0;
    for (size_t v = 0; v < mesh.positions.size(); ++v)
        if (index[v] != none)
        {
            index[v] = used;
            mesh.positions[used] = mesh.positions[v];
            if (per_vertex)
                (*per_vertex)[used] = (*per_vertex)[v];
            ++used;
        }
    mesh.positions.resize(used);
    if (per_vertex)
        per_vertex->resize(used);
    for (auto& t : mesh.triangles)
        for (uint32_t& v : t)
            v = index[v];
}

} // namespace zomeify
