#include "core/mesh/strut_rotation.h"
#include "core/mesh/dir3.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <queue>

namespace zomeify {

namespace {

using namespace dir3;

using Mat3 = std::array<Dir, 3>;

Dir times(const Mat3& m, const Dir& v) { return {dot(m[0], v), dot(m[1], v), dot(m[2], v)}; }

// The leading eigenvector and eigenvalue of a symmetric positive semi-definite 3×3 matrix by
// power iteration from its largest column (a fixed number of steps: deterministic).
std::pair<Dir, double> leading_eigen(const Mat3& m)
{
    Dir v = m[0];
    for (const Dir& row : m)
        if (dot(row, row) > dot(v, v))
            v = row;
    v = unit(v);
    for (int i = 0; i < 40 && dot(v, v) > 0; ++i)
        v = unit(times(m, v));
    return {v, dot(v, times(m, v))};
}

// An axis around which a node's struts keep their order. Away from the node, -Σ unit directions
// is the axis of a cone (corners and edges of a shape); on flat and nearly flat nodes it lies in
// the tangent plane, and the cross products of pairs of struts, all close to ± the normal, give
// it instead: their principal axis, used when it clearly dominates.
Dir axis_of(const std::vector<Dir>& d)
{
    Dir cone{0, 0, 0};
    Mat3 m{};
    for (size_t i = 0; i < d.size(); ++i)
    {
        cone = sub(cone, d[i]);
        for (size_t j = i + 1; j < d.size(); ++j)
        {
            const Dir c = cross(d[i], d[j]);
            for (size_t r = 0; r < 3; ++r)
                for (size_t k = 0; k < 3; ++k)
                    m[r][k] += c[r] * c[k];
        }
    }
    const auto [e1, l1] = leading_eigen(m);
    Mat3 rest = m;
    for (size_t r = 0; r < 3; ++r)
        for (size_t k = 0; k < 3; ++k)
            rest[r][k] -= l1 * e1[r] * e1[k];
    const double l2 = leading_eigen(rest).second;
    if (l1 > 3 * l2 || dot(cone, cone) == 0)
        return dot(e1, cone) < 0 ? neg(e1) : e1;
    return unit(cone);
}

// Neighbours sorted counter-clockwise around `normal` (no atan2: half-plane, then cross sign).
void sort_around(const Dir& normal, const std::vector<Dir>& d, std::vector<uint32_t>& nb)
{
    const Dir seed = std::abs(normal[0]) < 0.9 ? Dir{1, 0, 0} : Dir{0, 1, 0};
    const Dir t1 = unit(cross(seed, normal));
    const Dir t2 = cross(normal, t1);
    struct Item
    {
        double x, y;
        uint32_t node;
    };
    std::vector<Item> items;
    for (size_t i = 0; i < nb.size(); ++i)
        items.push_back({dot(d[i], t1), dot(d[i], t2), nb[i]});
    // 0: along the normal (no angle), 1: angles in [0, π), 2: angles in [π, 2π). Within a class the
    // cross product orders strictly, so the comparison is a strict weak order on every platform.
    auto half = [](const Item& a) { return a.x == 0 && a.y == 0 ? 0 : (a.y > 0 || (a.y == 0 && a.x > 0)) ? 1 : 2; };
    std::stable_sort(items.begin(), items.end(), [&](const Item& a, const Item& b) {
        const int ha = half(a), hb = half(b);
        if (ha != hb)
            return ha < hb;
        const double c = a.x * b.y - a.y * b.x;
        if (c != 0)
            return c > 0;
        return a.node < b.node;
    });
    for (size_t i = 0; i < nb.size(); ++i)
        nb[i] = items[i].node;
}

} // namespace

Rotation guess_rotation(const std::vector<ZVec>& nodes, const std::vector<std::array<uint32_t, 2>>& struts)
{
    const size_t n = nodes.size();
    Rotation nb(n);
    for (const auto& s : struts)
    {
        nb[s[0]].push_back(s[1]);
        nb[s[1]].push_back(s[0]);
    }
    std::vector<Dir> pos(n);
    for (size_t i = 0; i < n; ++i)
        pos[i] = nodes[i].to_double();
    auto directions = [&](size_t v) {
        std::vector<Dir> d;
        for (uint32_t u : nb[v])
            d.push_back(unit(sub(pos[u], pos[v])));
        return d;
    };
    std::vector<Dir> normal(n);
    for (size_t v = 0; v < n; ++v)
    {
        std::sort(nb[v].begin(), nb[v].end());
        normal[v] = axis_of(directions(v));
    }

    // Orientation: Prim's spanning tree over struts, most parallel normals first, per component
    // from its node of largest x (whose outward normal has x ≥ 0).
    std::vector<char> done(n, 0);
    std::vector<uint32_t> by_x(n);
    for (uint32_t i = 0; i < n; ++i)
        by_x[i] = i;
    std::stable_sort(by_x.begin(), by_x.end(), [&](uint32_t a, uint32_t b) { return pos[a][0] > pos[b][0]; });
    using Entry = std::tuple<double, uint32_t, uint32_t>; // (cost, node, from)
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (uint32_t root : by_x)
    {
        if (done[root])
            continue;
        if (normal[root][0] < 0)
            normal[root] = neg(normal[root]);
        queue.push({0.0, root, root});
        while (!queue.empty())
        {
            const auto [cost, v, from] = queue.top();
            queue.pop();
            if (done[v])
                continue;
            done[v] = 1;
            if (v != from && dot(normal[v], normal[from]) < 0)
                normal[v] = neg(normal[v]);
            for (uint32_t u : nb[v])
                if (!done[u])
                    queue.push({1.0 - std::abs(dot(normal[u], normal[v])), u, v});
        }
    }

    // Sort, then refine the normal by the link's area vector when it agrees, and sort again.
    for (size_t v = 0; v < n; ++v)
    {
        if (nb[v].size() < 3)
            continue;
        std::vector<Dir> d = directions(v);
        sort_around(normal[v], d, nb[v]);
        d = directions(v);
        Dir area{0, 0, 0};
        for (size_t i = 0; i < d.size(); ++i)
            area = add(area, cross(d[i], d[(i + 1) % d.size()]));
        if (dot(area, normal[v]) > 0)
            sort_around(unit(area), d, nb[v]);
    }
    return nb;
}

std::optional<Rotation> rotation_of_faces(size_t node_count, const std::vector<std::array<uint32_t, 2>>& struts,
                                          const std::vector<std::vector<uint32_t>>& faces)
{
    // next[v][w] = u: around v, u follows w counter-clockwise.
    std::vector<std::map<uint32_t, uint32_t>> next(node_count);
    for (const auto& f : faces)
        for (size_t i = 0; i < f.size(); ++i)
        {
            const uint32_t u = f[i], v = f[(i + 1) % f.size()], w = f[(i + 2) % f.size()];
            if (u >= node_count || v >= node_count || w >= node_count || !next[v].emplace(w, u).second)
                return std::nullopt;
        }
    std::vector<std::vector<uint32_t>> nb(node_count);
    for (const auto& s : struts)
    {
        nb[s[0]].push_back(s[1]);
        nb[s[1]].push_back(s[0]);
    }
    Rotation rotation(node_count);
    for (size_t v = 0; v < node_count; ++v)
    {
        auto& list = nb[v];
        std::sort(list.begin(), list.end());
        if (next[v].size() != list.size())
            return std::nullopt;
        if (list.empty())
            continue;
        // One cycle through exactly the neighbours.
        uint32_t at = list.front();
        for (size_t k = 0; k < list.size(); ++k)
        {
            if (!std::binary_search(list.begin(), list.end(), at))
                return std::nullopt;
            rotation[v].push_back(at);
            const auto it = next[v].find(at);
            if (it == next[v].end())
                return std::nullopt;
            at = it->second;
        }
        if (at != list.front())
            return std::nullopt;
        std::vector<uint32_t> sorted = rotation[v];
        std::sort(sorted.begin(), sorted.end());
        if (sorted != list)
            return std::nullopt;
    }
    return rotation;
}

} // namespace zomeify
