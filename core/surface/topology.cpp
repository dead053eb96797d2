#include "core/surface/topology.h"

#include <algorithm>
#include <numeric>

#include <Eigen/Geometry>

#include "core/surface/edge_uses.h"
#include "core/surface/nesting.h"
#include "core/surface/union_find.h"

namespace zomeify {

namespace {

constexpr uint32_t none = 0xFFFFFFFFu;

// Which neighbour each face has across each of its three edges (manifold edges only), and whether
// the two faces run along the shared edge in the same direction (inconsistent orientation).
struct Adjacency
{
    std::vector<uint32_t> neighbour; // 3 per face, `none` if boundary or non-manifold
    std::vector<uint8_t> same_direction;
};

} // namespace

TopologyInfo analyse_topology(const std::vector<Vec3>& positions, std::vector<std::array<uint32_t, 3>>& triangles,
                              const TopologyOptions& options)
{
    TopologyInfo info;
    const size_t nf = triangles.size();
    info.flipped.assign(nf, 0);

    // All directed edges grouped by undirected edge, in a deterministic order, with no hash map.
    const std::vector<EdgeUse> uses = sorted_edge_uses(triangles, positions.size());

    Adjacency adj{std::vector<uint32_t>(3 * nf, none), std::vector<uint8_t>(3 * nf, 0)};
    UnionFind faces(nf);
    UnionFind corners(3 * nf);
    UnionFind boundary(positions.size());
    std::vector<uint32_t> boundary_edge_face;
    std::vector<uint32_t> boundary_edge_vertex;
    std::vector<uint32_t> edge_face; // per unique edge: its first face (for per-component counts)
    for (size_t i = 0; i < uses.size();)
    {
        size_t j = i;
        while (j < uses.size() && uses[j].key == uses[i].key)
            ++j;
        const size_t count = j - i;
        const auto a = static_cast<uint32_t>(uses[i].key >> 32);
        const auto b = static_cast<uint32_t>(uses[i].key & 0xFFFFFFFFu);
        edge_face.push_back(uses[i].face);
        for (size_t k = i + 1; k < j; ++k)
            faces.unite(uses[i].face, uses[k].face);
        if (count == 1)
        {
            if (info.boundary_edges++ == 0)
                info.boundary_example = {a, b};
            boundary.unite(a, b);
            boundary_edge_face.push_back(uses[i].face);
            boundary_edge_vertex.push_back(a);
        }
        else if (count == 2)
        {
            const EdgeUse& u = uses[i];
            const EdgeUse& w = uses[i + 1];
            const uint32_t u_from = triangles[u.face][u.corner];
            const uint32_t w_from = triangles[w.face][w.corner];
            const bool same = u_from == w_from;
            adj.neighbour[3 * u.face + u.corner] = w.face;
            adj.neighbour[3 * w.face + w.corner] = u.face;
            adj.same_direction[3 * u.face + u.corner] = same;
            adj.same_direction[3 * w.face + w.corner] = same;
            // The corners at each end of the edge belong to one fan around that vertex.
            const uint32_t u_next = 3 * u.face + (u.corner + 1) % 3;
            const uint32_t w_next = 3 * w.face + (w.corner + 1) % 3;
            if (same)
            {
                corners.unite(3 * u.face + u.corner, 3 * w.face + w.corner);
                corners.unite(u_next, w_next);
            }
            else
            {
                corners.unite(3 * u.face + u.corner, w_next);
                corners.unite(u_next, 3 * w.face + w.corner);
            }
        }
        else if (info.non_manifold_edges++ == 0)
            info.non_manifold_edge_example = {a, b};
        i = j;
    }
    info.edges = edge_face.size();

    // Components, numbered in order of their first face.
    std::vector<uint32_t> component(nf);
    std::vector<uint32_t> root_to_component(nf, none);
    for (uint32_t f = 0; f < nf; ++f)
    {
        const uint32_t r = faces.find(f);
        if (root_to_component[r] == none)
            root_to_component[r] = static_cast<uint32_t>(info.components++);
        component[f] = root_to_component[r];
    }

    // Non-manifold vertices: the corners at a vertex form more than one fan.
    std::vector<uint32_t> first_fan(positions.size(), none);
    std::vector<uint8_t> is_non_manifold(positions.size(), 0);
    for (uint32_t c = 0; c < 3 * nf; ++c)
    {
        const uint32_t v = triangles[c / 3][c % 3];
        const uint32_t r = corners.find(c);
        if (first_fan[v] == none)
            first_fan[v] = r;
        else if (first_fan[v] != r && !is_non_manifold[v])
        {
            is_non_manifold[v] = 1;
            if (info.non_manifold_vertices++ == 0)
                info.non_manifold_vertex_example = v;
        }
    }
    for (const uint32_t f : first_fan)
        info.vertices += f != none;

    // Per-component Euler characteristic and boundary loops give the genus of each component.
    std::vector<long long> chi(info.components, 0);
    std::vector<long long> loops(info.components, 0);
    for (uint32_t f = 0; f < nf; ++f)
        ++chi[component[f]];
    for (const uint32_t f : edge_face)
        --chi[component[f]];
    std::vector<uint32_t> stamp(positions.size(), none);
    std::vector<uint32_t> order(nf);
    std::iota(order.begin(), order.end(), uint32_t{0});
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return component[a] < component[b]; });
    for (const uint32_t f : order)
        for (const uint32_t v : triangles[f])
            if (stamp[v] != component[f])
            {
                stamp[v] = component[f];
                ++chi[component[f]];
            }
    std::vector<uint8_t> loop_seen(positions.size(), 0);
    for (size_t e = 0; e < boundary_edge_vertex.size(); ++e)
    {
        const uint32_t r = boundary.find(boundary_edge_vertex[e]);
        if (!loop_seen[r])
        {
            loop_seen[r] = 1;
            ++info.holes;
            ++loops[component[boundary_edge_face[e]]];
        }
    }
    for (size_t c = 0; c < info.components; ++c)
        info.genus += (2 - chi[c] - loops[c]) / 2;
    info.euler =
        static_cast<long long>(info.vertices) - static_cast<long long>(info.edges) + static_cast<long long>(nf);

    // Consistent orientation: breadth-first over manifold edges; a face must run along a shared
    // edge opposite to its neighbour. A contradiction means the component is not orientable.
    std::vector<uint8_t> flip(nf, 0);
    std::vector<uint8_t> visited(nf, 0);
    std::vector<uint8_t> orientable(info.components, 1);
    std::vector<uint32_t> queue;
    for (uint32_t seed = 0; seed < nf; ++seed)
    {
        if (visited[seed])
            continue;
        visited[seed] = 1;
        queue.assign(1, seed);
        for (size_t q = 0; q < queue.size(); ++q)
        {
            const uint32_t f = queue[q];
            for (int k = 0; k < 3; ++k)
            {
                const uint32_t g = adj.neighbour[3 * f + k];
                if (g == none)
                    continue;
                const uint8_t want = flip[f] ^ adj.same_direction[3 * f + k];
                if (!visited[g])
                {
                    visited[g] = 1;
                    flip[g] = want;
                    queue.push_back(g);
                }
                else if (flip[g] != want)
                    orientable[component[f]] = 0;
            }
        }
    }
    for (size_t c = 0; c < info.components; ++c)
        info.non_orientable_components += !orientable[c];
    if (!options.orient)
        return info;

    // Outward: the signed volume of each component, taken about a point of that component so
    // that far-off coordinates do not cost precision, must be positive.
    std::vector<double> volume(info.components, 0.0);
    std::vector<uint32_t> anchor(info.components, none);
    for (uint32_t f = 0; f < nf; ++f)
    {
        const uint32_t c = component[f];
        if (anchor[c] == none)
            anchor[c] = triangles[f][0];
        const Vec3& o = positions[anchor[c]];
        const Vec3 a = positions[triangles[f][0]] - o;
        const Vec3 b = positions[triangles[f][1]] - o;
        const Vec3 d = positions[triangles[f][2]] - o;
        const double v = a.dot(b.cross(d));
        volume[c] += flip[f] ? -v : v;
    }
    for (uint32_t f = 0; f < nf; ++f)
    {
        const uint32_t c = component[f];
        if (orientable[c] && (flip[f] != (volume[c] < 0)))
        {
            std::swap(triangles[f][1], triangles[f][2]);
            info.flipped[f] = 1;
        }
    }

    // A closed shell inside an odd number of others bounds a cavity: it faces inward.
    std::vector<uint8_t> closed(info.components, 0);
    for (size_t c = 0; c < info.components; ++c)
        closed[c] = orientable[c] && loops[c] == 0;
    const std::vector<uint32_t> depth = nesting_depths(positions, triangles, component, closed);
    for (size_t c = 0; c < info.components; ++c)
        info.cavities += depth[c] % 2;
    for (uint32_t f = 0; f < nf; ++f)
        if (depth[component[f]] % 2)
        {
            std::swap(triangles[f][1], triangles[f][2]);
            info.flipped[f] ^= 1;
        }
    return info;
}

} // namespace zomeify
