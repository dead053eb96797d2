#include "core/surface/fill_holes.h"

#include <algorithm>
#include <limits>

#include <Eigen/Geometry>

#include "core/surface/edge_uses.h"

namespace zomeify {

namespace {

using Triangle = std::array<uint32_t, 3>;
constexpr uint32_t none = 0xFFFFFFFFu;

double area(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

// Least-area triangulation of the polygon `loop` (Barequet & Sharir; the core of Liepa's hole
// filling). Triangles keep the polygon's orientation. A triangle of three collinear rim vertices
// (a straight stretch of the rim) would cost nothing, so it is charged more than any real one; a
// diagonal that is already an edge of the mesh (the rim passes twice near one place) would give
// that edge a third face, so it is charged more still.
void least_area_patch(const std::vector<Vec3>& positions, const std::vector<uint32_t>& loop,
                      const std::vector<uint64_t>& mesh_edges, std::vector<Triangle>& out)
{
    const size_t n = loop.size();
    double perimeter = 0.0;
    for (size_t i = 0; i < n; ++i)
        perimeter += (positions[loop[(i + 1) % n]] - positions[loop[i]]).norm();
    const double flat = 1e-12 * perimeter * perimeter;
    const double penalty = perimeter * perimeter;
    const auto weight = [&](size_t i, size_t m, size_t j) {
        const double a = area(positions[loop[i]], positions[loop[m]], positions[loop[j]]);
        return a <= flat ? a + penalty : a;
    };
    std::vector<double> cost(n * n, 0.0);
    std::vector<uint32_t> split(n * n, 0);
    const auto at = [n](size_t i, size_t j) { return i * n + j; };
    const auto taken = [&](size_t i, size_t j) {
        const uint32_t a = loop[i], b = loop[j];
        return std::binary_search(mesh_edges.begin(), mesh_edges.end(),
                                  (uint64_t{std::min(a, b)} << 32) | std::max(a, b));
    };
    for (size_t span = 2; span < n; ++span)
        for (size_t i = 0; i + span < n; ++i)
        {
            const size_t j = i + span;
            const double diagonal = span < n - 1 && taken(i, j) ? n * penalty : 0.0;
            double best = std::numeric_limits<double>::infinity();
            for (size_t m = i + 1; m < j; ++m)
            {
                const double c = cost[at(i, m)] + cost[at(m, j)] + weight(i, m, j);
                // The first split is taken whatever its cost, so an overflowing (infinite or NaN)
                // cost still leaves a valid triangulation.
                if (m == i + 1 || c < best)
                {
                    best = c;
                    split[at(i, j)] = static_cast<uint32_t>(m);
                }
            }
            cost[at(i, j)] = best + diagonal;
        }
    std::vector<std::pair<size_t, size_t>> pending{{0, n - 1}}; // sub-polygons still to emit
    while (!pending.empty())
    {
        const auto [i, j] = pending.back();
        pending.pop_back();
        if (j - i < 2)
            continue;
        const size_t m = split[at(i, j)];
        out.push_back({loop[i], loop[m], loop[j]});
        pending.emplace_back(i, m);
        pending.emplace_back(m, j);
    }
}

void centroid_fan(std::vector<Vec3>& positions, std::vector<uint32_t>& origin, const std::vector<uint32_t>& loop,
                  std::vector<Triangle>& out)
{
    Vec3 centre = Vec3::Zero();
    for (const uint32_t v : loop)
        centre += positions[v];
    centre /= static_cast<double>(loop.size());
    const auto c = static_cast<uint32_t>(positions.size());
    positions.push_back(centre);
    origin.push_back(none); // a new vertex, not in the input
    for (size_t i = 0; i < loop.size(); ++i)
        out.push_back({loop[i], loop[(i + 1) % loop.size()], c});
}

} // namespace

HoleFilling fill_holes(std::vector<Vec3>& positions, std::vector<Triangle>& triangles, std::vector<uint32_t>& origin)
{
    HoleFilling out;
    // Directed edges used once (their reverse never): the rim of a hole, in the faces' direction.
    const std::vector<EdgeUse> edges = sorted_edge_uses(triangles, positions.size());
    // Every edge of the mesh, sorted (so the patches can avoid them as diagonals).
    std::vector<uint64_t> mesh_edges;
    mesh_edges.reserve(edges.size() / 2);
    for (const EdgeUse& e : edges)
        if (mesh_edges.empty() || mesh_edges.back() != e.key)
            mesh_edges.push_back(e.key);
    std::vector<uint32_t> next(positions.size(), none);
    std::vector<uint32_t> rim_face(positions.size(), none);
    std::vector<uint8_t> ambiguous(positions.size(), 0);
    std::vector<uint32_t> starts;
    for (size_t i = 0; i < edges.size();)
    {
        size_t j = i + 1;
        while (j < edges.size() && edges[j].key == edges[i].key)
            ++j;
        if (j - i == 1)
        {
            const EdgeUse& e = edges[i];
            const uint32_t from = triangles[e.face][e.corner], to = triangles[e.face][(e.corner + 1) % 3];
            if (next[from] != none)
                ambiguous[from] = 1;
            next[from] = to;
            rim_face[from] = e.face;
            starts.push_back(from);
        }
        i = j;
    }

    std::vector<uint8_t> done(positions.size(), 0);
    std::vector<uint32_t> loop;
    for (const uint32_t start : starts)
    {
        if (done[start])
            continue;
        loop.clear();
        bool simple = true;
        uint32_t v = start;
        while (v != none && !done[v])
        {
            done[v] = 1;
            simple = simple && !ambiguous[v];
            loop.push_back(v);
            v = next[v];
        }
        if (!simple || v != start || loop.size() < 3)
        {
            ++out.untraceable;
            continue;
        }
        // The patch runs along the rim the other way.
        std::reverse(loop.begin(), loop.end());
        FilledHole hole;
        hole.edges = loop.size();
        hole.neighbour = rim_face[start];
        hole.first_patch = static_cast<uint32_t>(triangles.size());
        if (loop.size() <= kMaxExactLoop)
            least_area_patch(positions, loop, mesh_edges, triangles);
        else
            centroid_fan(positions, origin, loop, triangles);
        hole.patch_faces = static_cast<uint32_t>(triangles.size()) - hole.first_patch;
        for (size_t t = hole.first_patch; t < triangles.size(); ++t)
            hole.area += area(positions[triangles[t][0]], positions[triangles[t][1]], positions[triangles[t][2]]);
        out.holes.push_back(hole);
    }
    return out;
}

} // namespace zomeify
