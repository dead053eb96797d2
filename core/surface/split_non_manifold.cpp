#include "core/surface/split_non_manifold.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "core/surface/edge_uses.h"
#include "core/surface/union_find.h"

namespace zomeify {

namespace {

constexpr uint32_t none = 0xFFFFFFFFu;

// Corners of two faces that share edge (u.face's corner u.corner → next) lie in one fan at each end.
void join_across(UnionFind& fans, const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeUse& u,
                 const EdgeUse& w)
{
    const uint32_t u_from = 3 * u.face + u.corner, u_to = 3 * u.face + (u.corner + 1) % 3;
    const uint32_t w_from = 3 * w.face + w.corner, w_to = 3 * w.face + (w.corner + 1) % 3;
    if (triangles[u.face][u.corner] == triangles[w.face][w.corner])
    {
        fans.unite(u_from, w_from);
        fans.unite(u_to, w_to);
    }
    else
    {
        fans.unite(u_from, w_to);
        fans.unite(u_to, w_from);
    }
}

// Pairs the k > 2 faces around edge a–b (a < b): sorted by angle about the edge, a face whose
// normal points toward increasing angle (it runs b→a) closes a wedge of solid with the next face
// if that one runs a→b. Returns the number of faces left unpaired.
size_t pair_around_edge(UnionFind& fans, const std::vector<Vec3>& positions,
                        const std::vector<std::array<uint32_t, 3>>& triangles, const EdgeUse* uses, size_t k)
{
    const auto a = static_cast<uint32_t>(uses[0].key >> 32);
    const auto b = static_cast<uint32_t>(uses[0].key & 0xFFFFFFFFu);
    const Vec3 d = (positions[b] - positions[a]).normalized();
    const Vec3 x = d.unitOrthogonal();
    const Vec3 y = d.cross(x);
    struct Around
    {
        double angle;
        bool forward; // runs a → b
        size_t use;
    };
    std::vector<Around> around(k);
    for (size_t i = 0; i < k; ++i)
    {
        const auto& t = triangles[uses[i].face];
        const uint8_t c = uses[i].corner;
        const Vec3 w = positions[t[(c + 2) % 3]] - positions[a];
        around[i] = {std::atan2(w.dot(y), w.dot(x)), t[c] == a, i};
    }
    std::sort(around.begin(), around.end(),
              [](const Around& p, const Around& q) { return p.angle != q.angle ? p.angle < q.angle : p.use < q.use; });
    size_t paired = 0;
    for (size_t i = 0; i < k; ++i)
    {
        const Around& p = around[i];
        const Around& q = around[(i + 1) % k];
        if (!p.forward && q.forward)
        {
            join_across(fans, triangles, uses[p.use], uses[q.use]);
            paired += 2;
        }
    }
    return k - paired;
}

} // namespace

NonManifoldSplit split_non_manifold(std::vector<Vec3>& positions, std::vector<std::array<uint32_t, 3>>& triangles,
                                    std::vector<uint32_t>& origin)
{
    NonManifoldSplit out;
    const size_t nf = triangles.size();
    const std::vector<EdgeUse> uses = sorted_edge_uses(triangles, positions.size());

    // Fans: corners joined across every edge that two faces share (as analyse_topology counts them).
    UnionFind fans(3 * nf);
    std::vector<uint8_t> on_split_edge(positions.size(), 0);
    for (size_t i = 0; i < uses.size();)
    {
        size_t j = i;
        while (j < uses.size() && uses[j].key == uses[i].key)
            ++j;
        if (j - i == 2)
            join_across(fans, triangles, uses[i], uses[i + 1]);
        else if (j - i > 2)
        {
            ++out.split_edges;
            on_split_edge[uses[i].key >> 32] = 1;
            on_split_edge[uses[i].key & 0xFFFFFFFFu] = 1;
            out.loose_faces += pair_around_edge(fans, positions, triangles, &uses[i], j - i);
        }
        i = j;
    }

    // The first fan met at a vertex keeps it; every other fan gets a copy.
    std::vector<uint32_t> fan_vertex(3 * nf, none);
    std::vector<uint8_t> taken(positions.size(), 0);
    std::vector<uint8_t> counted(positions.size(), 0);
    for (uint32_t c = 0; c < 3 * nf; ++c)
    {
        uint32_t& v = triangles[c / 3][c % 3];
        const uint32_t root = fans.find(c);
        if (fan_vertex[root] == none)
        {
            if (!taken[v])
            {
                taken[v] = 1;
                fan_vertex[root] = v;
            }
            else
            {
                if (!counted[v] && !on_split_edge[v])
                {
                    counted[v] = 1;
                    ++out.pinched_vertices;
                }
                fan_vertex[root] = static_cast<uint32_t>(positions.size());
                positions.push_back(positions[v]);
                origin.push_back(origin[v]);
            }
        }
        v = fan_vertex[root];
    }
    return out;
}

} // namespace zomeify
